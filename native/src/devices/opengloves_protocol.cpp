// SPDX-License-Identifier: MIT
#include "devices/opengloves_protocol.h"

#include <string_view>

#include "devices/alpha_encoding.h"

namespace frusta {

DeviceCapabilities OpenGlovesProtocol::default_capabilities() const {
  DeviceCapabilities caps;
  caps.outputs = kOutputFingerResistance;
  caps.max_finger_resistance = calibration_.brake_full_scale;
  caps.input_rate_hz = 100.0;   // LucidGloves' loop, roughly
  caps.output_rate_hz = 100.0;  // a 25-byte line each 10 ms fits 115200 baud with room
  return caps;
}

void OpenGlovesProtocol::start(std::vector<uint8_t>* /*out*/) {
  length_ = 0;
  overlong_ = false;
}

void OpenGlovesProtocol::feed(const uint8_t* data, size_t size, ProtocolSink* sink) {
  for (size_t i = 0; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n') {
      end_line(sink);
    } else if (length_ < kMaxLine) {
      line_[length_++] = c;
    } else if (!overlong_) {
      overlong_ = true;
      sink->on_fault(FrameFault::kTruncated);
    }
  }
}

void OpenGlovesProtocol::end_line(ProtocolSink* sink) {
  const bool overlong = overlong_;
  const std::string_view line(line_.data(), length_);
  length_ = 0;
  overlong_ = false;
  if (overlong) return;  // counted when it overflowed
  RawGloveReading raw;
  switch (decode_alpha_line(line, calibration_.analog_max, &raw)) {
    case AlphaLine::kSample: {
      DeviceSample sample;
      raw_to_joint_angles(calibration_, raw, angles_, &sample.angles);
      angles_ = sample.angles;
      sink->on_sample(sample);
      break;
    }
    case AlphaLine::kNoFingers: sink->on_heartbeat(); break;
    case AlphaLine::kCorrupt: sink->on_fault(FrameFault::kCorrupt); break;
    case AlphaLine::kTruncated: sink->on_fault(FrameFault::kTruncated); break;
    case AlphaLine::kOutOfRange: sink->on_fault(FrameFault::kOutOfRange); break;
  }
}

void OpenGlovesProtocol::encode(const DeviceCommand& command, const DeviceCapabilities& capabilities,
                                std::vector<uint8_t>* out) {
  if (!(capabilities.outputs & kOutputFingerResistance)) return;
  std::array<int32_t, FRUSTA_FINGER_COUNT> units{};
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    units[f] = resistance_to_brake_units(calibration_, command.finger_resistance[f]);
  char line[40];
  const size_t n = encode_alpha_brakes(units, line, sizeof line);
  out->insert(out->end(), line, line + n);
}

void OpenGlovesProtocol::encode_heartbeat(std::vector<uint8_t>* /*out*/) {}

}  // namespace frusta
