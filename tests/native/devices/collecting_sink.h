// SPDX-License-Identifier: MIT
// A ProtocolSink that keeps what a protocol decoded, for the codec tests.
#pragma once

#include <vector>

#include "devices/glove_protocol.h"

namespace frusta {

struct Collect final : ProtocolSink {
  std::vector<DeviceSample> samples;
  std::vector<DeviceCapabilities> capabilities;
  int corrupt = 0, truncated = 0, out_of_range = 0, heartbeats = 0;
  void on_sample(const DeviceSample& s) override { samples.push_back(s); }
  void on_capabilities(const DeviceCapabilities& c) override { capabilities.push_back(c); }
  void on_fault(FrameFault f) override {
    (f == FrameFault::kCorrupt ? corrupt : f == FrameFault::kTruncated ? truncated : out_of_range)++;
  }
  void on_heartbeat() override { ++heartbeats; }
};

}  // namespace frusta
