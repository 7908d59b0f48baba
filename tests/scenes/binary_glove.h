// SPDX-License-Identifier: MIT
// The glove's side of our binary profile, as a glove maker's firmware would run it on
// a SimulatedGlove: answers each HELLO with its CAPS, sends a SAMPLE a tick, and keeps
// the COMMANDs it is sent. The angles it reports are set from any thread.
#pragma once

#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "devices/frusta_protocol.h"
#include "scenes/simulated_glove.h"

namespace frusta::scenes {

class BinaryGlove final : private binary_profile::HostSink {
 public:
  struct ReceivedCommand {
    int64_t time_ns;  // steady clock
    binary_profile::Command command;
  };

  explicit BinaryGlove(const DeviceCapabilities& capabilities);

  SimulatedGlove::Firmware firmware();
  SimulatedGlove::Listener listener();

  void set_angle(int joint, double radians);
  void set_answering(bool answering);  // false: HELLOs go unanswered

  int hellos() const;
  int faults() const;
  int64_t samples_sent() const;
  // COMMANDs from index `from` on (in order of arrival)
  std::vector<ReceivedCommand> commands(size_t from = 0) const;

 private:
  void on_hello(const binary_profile::Hello& hello) override;
  void on_command(const binary_profile::Command& command) override;
  void on_heartbeat() override {}
  void on_fault(FrameFault fault) override;

  const DeviceCapabilities capabilities_;
  binary_profile::GloveSideDecoder decoder_;  // the glove thread's
  mutable std::mutex mutex_;
  DeviceSample sample_;
  bool answering_ = true;
  bool caps_due_ = false;
  int hellos_ = 0, faults_ = 0;
  int64_t samples_sent_ = 0;
  uint16_t sequence_ = 0;
  std::vector<ReceivedCommand> commands_;
};

}  // namespace frusta::scenes
