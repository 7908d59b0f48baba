// SPDX-License-Identifier: MIT
// The glove's side of our binary profile, as a glove maker's firmware would run it on
// a SimulatedGlove: answers each HELLO with its CAPS, sends a SAMPLE a tick, and keeps
// the COMMANDs it is sent. The angles it reports are set from any thread. Each SAMPLE
// carries the glove's own clock, tick / sample_rate_hz: the time it was due, whenever
// the simulating thread got to send it, as a glove's crystal would stamp it.
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

  // sample_rate_hz: how fast it really samples (0: as it announces)
  explicit BinaryGlove(const DeviceCapabilities& capabilities, double sample_rate_hz = 0.0);

  SimulatedGlove::Firmware firmware();
  SimulatedGlove::Listener listener();

  void set_angle(int joint, double radians);
  void set_answering(bool answering);  // false: HELLOs go unanswered

  int hellos() const;
  int heartbeats() const;
  int hellos_after_heartbeat() const;  // the host's handshake is over at its first HEARTBEAT
  int faults() const;
  int64_t samples_sent() const;
  // COMMANDs from index `from` on (in order of arrival)
  std::vector<ReceivedCommand> commands(size_t from = 0) const;

 private:
  void on_hello(const binary_profile::Hello& hello) override;
  void on_command(const binary_profile::Command& command) override;
  void on_heartbeat() override;
  void on_fault(FrameFault fault) override;

  const DeviceCapabilities capabilities_;
  const double sample_rate_hz_;
  binary_profile::GloveSideDecoder decoder_;  // the glove thread's
  mutable std::mutex mutex_;
  DeviceSample sample_;
  bool answering_ = true;
  bool caps_due_ = false;
  int hellos_ = 0, heartbeats_ = 0, hellos_after_heartbeat_ = 0, faults_ = 0;
  int64_t samples_sent_ = 0;
  uint16_t sequence_ = 0;
  std::vector<ReceivedCommand> commands_;
};

}  // namespace frusta::scenes
