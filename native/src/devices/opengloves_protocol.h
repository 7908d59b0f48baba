// SPDX-License-Identifier: MIT
// The OpenGloves alpha encoding as a GloveProtocol: lines to calibrated samples, the
// world's finger resistances to brake lines. The encoding has no handshake and no
// capabilities: a glove speaking it is taken to have five brakes and no tracker.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "devices/glove_calibration.h"
#include "devices/glove_protocol.h"

namespace frusta {

class OpenGlovesProtocol final : public GloveProtocol {
 public:
  // `calibration` must have passed check_glove_calibration.
  explicit OpenGlovesProtocol(const GloveCalibration& calibration) : calibration_(calibration) {}

  DeviceCapabilities default_capabilities() const override;
  void start(std::vector<uint8_t>* out) override;
  void feed(const uint8_t* data, size_t size, ProtocolSink* sink) override;
  void encode(const DeviceCommand& command, const DeviceCapabilities& capabilities,
              std::vector<uint8_t>* out) override;
  void encode_heartbeat(std::vector<uint8_t>* out) override;

  // LucidGloves lines are under 100 bytes; a longer one lost its newline
  static constexpr size_t kMaxLine = 256;

 private:
  void end_line(ProtocolSink* sink);

  GloveCalibration calibration_;
  std::array<char, kMaxLine> line_{};
  size_t length_ = 0;
  bool overlong_ = false;  // dropping the rest of a line that outgrew kMaxLine
  std::array<double, FRUSTA_HAND_JOINT_COUNT> angles_{};  // the last sample's
};

}  // namespace frusta
