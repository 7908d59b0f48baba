// SPDX-License-Identifier: MIT
// libFuzzer target: the bytes a glove sends, through the host's decoders (OpenGloves'
// alpha lines, Frusta's binary profile), must decode without a crash, a sanitizer
// report or unbounded memory, to samples and capabilities within what the engine
// takes (finite angles within pi to the field's resolution, a unit palm rotation, a palm
// within 1 km, known outputs), and to the same events whether the bytes come whole or in
// chunks (a serial port hands them over in any chunks).
//
// Random bytes almost never carry a good CRC, so a plain fuzzer stops at the binary
// profile's framing. Byte 0 chooses the decoder; for the binary profile, half the
// inputs are a list of records made into frames with their CRC computed here: a
// record with the high bit set is that many raw bytes (garbage between frames), one
// without it a frame of type, length and payload.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <memory>
#include <vector>

#include "devices/frusta_protocol.h"
#include "devices/glove_calibration.h"
#include "devices/opengloves_protocol.h"

namespace {

using namespace frusta;

// what a decoder reported, in order, checked as it came
struct Events final : ProtocolSink {
  std::vector<uint8_t> log;  // every event's bytes, to compare two feeds
  template <class T>
  void keep(uint8_t kind, const T& value) {
    log.push_back(kind);
    const auto* bytes = reinterpret_cast<const uint8_t*>(&value);
    log.insert(log.end(), bytes, bytes + sizeof value);
  }
  void on_sample(const DeviceSample& s) override {
    // pi as the binary profile counts it, rounded to its 1e-4 rad: 31416 counts is pi
    // sent by a glove, 7e-6 rad over it (the first finding, glove_seeds/)
    for (double a : s.angles)
      if (!(std::fabs(a) <= binary_profile::kMaxAngleCounts * binary_profile::kAngleUnit))
        std::abort();
    // 1 km as the profile counts it: 10^8 counts of 10 um decode to 1 km and a rounding
    // (the second finding, glove_seeds/)
    if (s.has_palm_pose) {
      for (int i = 0; i < 3; ++i)
        if (!(std::fabs(s.palm_position[i]) <=
              binary_profile::kMaxPositionCounts * binary_profile::kPositionUnit))
          std::abort();
      const glm::dquat& q = s.palm_rotation;
      if (!(std::fabs(glm::length(q) - 1.0) <= 1e-9)) std::abort();
    }
    if (s.device_time_us < -1 || s.sequence < -1) std::abort();
    keep(1, s.angles);
    keep(2, s.has_palm_pose);
    if (s.has_palm_pose) {
      keep(3, s.palm_position);
      keep(4, s.palm_rotation);
    }
    keep(5, s.device_time_us);
    keep(6, s.sequence);
  }
  void on_capabilities(const DeviceCapabilities& c) override {
    const uint32_t known = kOutputFingerResistance | kOutputFingertipForce | kOutputJointTorque;
    if (c.fingers < 0 || c.fingers > FRUSTA_FINGER_COUNT || (c.outputs & ~known) != 0) std::abort();
    for (double v : {c.max_finger_resistance, c.max_fingertip_force, c.max_joint_torque,
                     c.input_rate_hz, c.output_rate_hz})
      if (!(v >= 0.0 && std::isfinite(v))) std::abort();
    if (!(c.input_rate_hz > 0.0) || (c.outputs != 0 && !(c.output_rate_hz > 0.0))) std::abort();
    keep(7, c.fingers);
    keep(8, c.outputs);
    keep(9, c.max_finger_resistance);
    keep(10, c.input_rate_hz);
  }
  void on_fault(FrameFault fault) override { keep(11, fault); }
  void on_heartbeat() override { log.push_back(12); }
};

std::unique_ptr<GloveProtocol> make(bool binary) {
  if (binary) return std::make_unique<FrustaProtocol>();
  return std::make_unique<OpenGlovesProtocol>(default_glove_calibration());
}

// records to frames (see the top): CRC-16/CCITT-FALSE over type, length and payload,
// little-endian after them, as binary_profile.md has it
std::vector<uint8_t> framed(const uint8_t* data, size_t size) {
  std::vector<uint8_t> out;
  size_t i = 0;
  while (i < size) {
    const uint8_t tag = data[i++];
    if (tag & 0x80) {
      const size_t n = std::min<size_t>(tag & 0x7f, size - i);
      out.insert(out.end(), data + i, data + i + n);
      i += n;
      continue;
    }
    if (i + 2 > size) break;
    const uint8_t type = data[i++];
    const size_t length = std::min<size_t>(data[i++], size - i);
    const size_t start = out.size();
    out.push_back(binary_profile::kSync);
    out.push_back(type);
    out.push_back(static_cast<uint8_t>(length));
    out.insert(out.end(), data + i, data + i + length);
    i += length;
    const uint16_t crc = binary_profile::crc16(out.data() + start + 1, length + 2);
    out.push_back(static_cast<uint8_t>(crc));
    out.push_back(static_cast<uint8_t>(crc >> 8));
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const bool binary = (data[0] & 1) != 0;
  const size_t chunk = 1 + data[1] % 64;
  const std::vector<uint8_t> stream = binary && (data[0] & 2)
                                          ? framed(data + 2, size - 2)
                                          : std::vector<uint8_t>(data + 2, data + size);
  std::vector<uint8_t> handshake;
  Events whole, pieces;
  std::unique_ptr<GloveProtocol> a = make(binary), b = make(binary);
  a->start(&handshake);
  b->start(&handshake);
  a->feed(stream.data(), stream.size(), &whole);
  for (size_t at = 0; at < stream.size(); at += chunk)
    b->feed(stream.data() + at, std::min(chunk, stream.size() - at), &pieces);
  if (whole.log != pieces.log) std::abort();  // the chunking changed what was decoded
  return 0;
}
