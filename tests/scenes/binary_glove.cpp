// SPDX-License-Identifier: MIT
#include "scenes/binary_glove.h"

#include <chrono>
#include <cmath>

namespace frusta::scenes {

BinaryGlove::BinaryGlove(const DeviceCapabilities& capabilities, double sample_rate_hz)
    : capabilities_(capabilities),
      sample_rate_hz_(sample_rate_hz > 0.0 ? sample_rate_hz : capabilities.input_rate_hz) {}

SimulatedGlove::Firmware BinaryGlove::firmware() {
  return [this](int64_t tick) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<uint8_t> out;
    if (caps_due_) binary_profile::encode_caps(capabilities_, &out);
    caps_due_ = false;
    DeviceSample sample = sample_;
    sample.device_time_us = std::llround(static_cast<double>(tick) * 1e6 / sample_rate_hz_);
    binary_profile::encode_sample(sample, sequence_++, &out);
    ++samples_sent_;
    return std::string(out.begin(), out.end());
  };
}

SimulatedGlove::Listener BinaryGlove::listener() {
  return [this](const std::string& bytes) {
    decoder_.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), this);
  };
}

void BinaryGlove::set_angle(int joint, double radians) {
  std::lock_guard<std::mutex> lock(mutex_);
  sample_.angles[static_cast<size_t>(joint)] = radians;
}

void BinaryGlove::set_answering(bool answering) {
  std::lock_guard<std::mutex> lock(mutex_);
  answering_ = answering;
}

int BinaryGlove::hellos() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hellos_;
}

int BinaryGlove::heartbeats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return heartbeats_;
}

int BinaryGlove::hellos_after_heartbeat() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hellos_after_heartbeat_;
}

int BinaryGlove::faults() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return faults_;
}

int64_t BinaryGlove::samples_sent() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return samples_sent_;
}

std::vector<BinaryGlove::ReceivedCommand> BinaryGlove::commands(size_t from) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (from >= commands_.size()) return {};
  return std::vector<ReceivedCommand>(commands_.begin() + static_cast<std::ptrdiff_t>(from),
                                      commands_.end());
}

void BinaryGlove::on_hello(const binary_profile::Hello&) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++hellos_;
  if (heartbeats_ > 0) ++hellos_after_heartbeat_;
  caps_due_ = answering_;
}

void BinaryGlove::on_command(const binary_profile::Command& command) {
  const int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                          std::chrono::steady_clock::now().time_since_epoch())
                          .count();
  std::lock_guard<std::mutex> lock(mutex_);
  commands_.push_back(ReceivedCommand{now, command});
}

void BinaryGlove::on_heartbeat() {
  std::lock_guard<std::mutex> lock(mutex_);
  ++heartbeats_;
}

void BinaryGlove::on_fault(FrameFault) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++faults_;
}

}  // namespace frusta::scenes
