// SPDX-License-Identifier: MIT
#include "devices/frusta_protocol.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/gtc/quaternion.hpp>

namespace frusta {

namespace binary_profile {

namespace {

// ---- little-endian fields

void put_u8(uint8_t value, std::vector<uint8_t>* out) { out->push_back(value); }

void put_u16(uint16_t value, std::vector<uint8_t>* out) {
  out->push_back(static_cast<uint8_t>(value));
  out->push_back(static_cast<uint8_t>(value >> 8));
}

void put_i16(int16_t value, std::vector<uint8_t>* out) { put_u16(static_cast<uint16_t>(value), out); }

void put_u32(uint32_t value, std::vector<uint8_t>* out) {
  put_u16(static_cast<uint16_t>(value), out);
  put_u16(static_cast<uint16_t>(value >> 16), out);
}

uint16_t get_u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | p[1] << 8); }
int16_t get_i16(const uint8_t* p) { return static_cast<int16_t>(get_u16(p)); }
uint32_t get_u32(const uint8_t* p) {
  return static_cast<uint32_t>(get_u16(p)) | static_cast<uint32_t>(get_u16(p + 2)) << 16;
}
int32_t get_i32(const uint8_t* p) { return static_cast<int32_t>(get_u32(p)); }

// ---- quantisation: round to the unit, clamp to the field, NaN to `if_nan`

int16_t to_i16(double value, double unit, int16_t if_nan) {
  if (std::isnan(value)) return if_nan;
  return static_cast<int16_t>(std::clamp(std::round(value / unit), -32767.0, 32767.0));
}

uint16_t to_u16(double value, double unit) {
  if (std::isnan(value)) return 0;
  return static_cast<uint16_t>(std::clamp(std::round(value / unit), 0.0, 65535.0));
}

int32_t to_i32(double value, double unit) {
  if (std::isnan(value)) return std::numeric_limits<int32_t>::min();
  return static_cast<int32_t>(std::clamp(std::round(value / unit), -2147483647.0, 2147483647.0));
}

// ---- frames

size_t begin_frame(MessageType type, std::vector<uint8_t>* out) {
  const size_t start = out->size();
  out->push_back(kSync);
  out->push_back(type);
  out->push_back(0);  // length, once the payload is in
  return start;
}

void end_frame(size_t start, std::vector<uint8_t>* out) {
  uint8_t* frame = out->data() + start;
  const size_t length = out->size() - start - kHeaderSize;
  frame[2] = static_cast<uint8_t>(length);
  put_u16(crc16(frame + 1, length + 2), out);
}

// the smallest payload a type may have; unknown types none
size_t min_payload(uint8_t type) {
  switch (type) {
    case kHello: return kHelloSize;
    case kCaps: return kCapsSize;
    case kSample: return kSampleSize;
    case kCommand: return kCommandSize;
    case kHeartbeat: return 0;
    default: return std::numeric_limits<size_t>::max();
  }
}

size_t command_size(uint32_t outputs) {
  size_t size = kCommandSize;
  if (outputs & kOutputFingerResistance) size += kResistanceBlockSize;
  if (outputs & kOutputFingertipForce) size += kForceBlockSize;
  if (outputs & kOutputJointTorque) size += kTorqueBlockSize;
  return size;
}


// what a payload of the glove's told the host
enum class Verdict { kGood, kCorrupt, kOutOfRange };

Verdict decode_caps(const uint8_t* payload, DeviceCapabilities* caps) {
  caps->protocol_version = get_u16(payload);
  caps->fingers = payload[2];
  caps->outputs = payload[3] & kKnownOutputs;
  caps->has_palm_pose = (payload[4] & kCapsHasPalmPose) != 0;
  caps->max_finger_resistance = get_u16(payload + 6) * kForceUnit;
  caps->max_fingertip_force = get_u16(payload + 8) * kForceUnit;
  caps->max_joint_torque = get_u16(payload + 10) * kTorqueUnit;
  caps->input_rate_hz = get_u16(payload + 12);
  caps->output_rate_hz = get_u16(payload + 14);
  const bool usable = (caps->protocol_version >> 8) == (kVersion >> 8) &&
                      caps->fingers <= FRUSTA_FINGER_COUNT && caps->input_rate_hz > 0.0 &&
                      (caps->outputs == 0 || caps->output_rate_hz > 0.0);
  return usable ? Verdict::kGood : Verdict::kOutOfRange;
}

// All of *sample but device_time_us; *time is the glove's clock as sent.
Verdict decode_sample(const uint8_t* payload, size_t size, DeviceSample* sample, uint32_t* time) {
  const bool has_palm = (payload[6] & kSampleHasPalmPose) != 0;
  if (has_palm && size < kSampleSize + kPalmPoseSize) return Verdict::kCorrupt;
  *time = get_u32(payload + 2);
  const uint8_t* p = payload + 7;
  for (double& angle : sample->angles) {
    const int16_t counts = get_i16(p);
    p += 2;
    if (std::abs(counts) > kMaxAngleCounts) return Verdict::kOutOfRange;
    angle = counts * kAngleUnit;
  }
  sample->has_palm_pose = has_palm;
  if (!has_palm) {
    sample->palm_position = vec3(0.0);
    sample->palm_rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
    return Verdict::kGood;
  }
  for (int i = 0; i < 3; ++i) {
    const int32_t counts = get_i32(p);
    p += 4;
    if (counts < -kMaxPositionCounts || counts > kMaxPositionCounts) return Verdict::kOutOfRange;
    sample->palm_position[i] = counts * kPositionUnit;
  }
  const glm::dquat q(get_i16(p) / kQuaternionScale, get_i16(p + 2) / kQuaternionScale,
                     get_i16(p + 4) / kQuaternionScale, get_i16(p + 6) / kQuaternionScale);
  if (std::fabs(glm::length(q) - 1.0) > kMaxQuaternionNormError) return Verdict::kOutOfRange;
  sample->palm_rotation = glm::normalize(q);
  return Verdict::kGood;
}
}  // namespace

uint16_t crc16(const uint8_t* data, size_t size) {
  uint16_t crc = 0xFFFF;
  for (size_t i = 0; i < size; ++i) {
    crc = static_cast<uint16_t>(crc ^ data[i] << 8);
    for (int bit = 0; bit < 8; ++bit)
      crc = static_cast<uint16_t>(crc & 0x8000 ? crc << 1 ^ 0x1021 : crc << 1);
  }
  return crc;
}

void encode_hello(const Hello& hello, std::vector<uint8_t>* out) {
  const size_t start = begin_frame(kHello, out);
  put_u16(hello.version, out);
  put_u16(hello.sample_rate_hz, out);
  put_u16(hello.command_rate_hz, out);
  end_frame(start, out);
}

void encode_caps(const DeviceCapabilities& caps, std::vector<uint8_t>* out) {
  const size_t start = begin_frame(kCaps, out);
  put_u16(caps.protocol_version != 0 ? static_cast<uint16_t>(caps.protocol_version) : kVersion,
          out);
  put_u8(static_cast<uint8_t>(std::clamp(caps.fingers, 0, 255)), out);
  put_u8(static_cast<uint8_t>(caps.outputs & 0xFF), out);
  put_u8(caps.has_palm_pose ? kCapsHasPalmPose : 0, out);
  put_u8(0, out);  // reserved
  put_u16(to_u16(caps.max_finger_resistance, kForceUnit), out);
  put_u16(to_u16(caps.max_fingertip_force, kForceUnit), out);
  put_u16(to_u16(caps.max_joint_torque, kTorqueUnit), out);
  put_u16(to_u16(caps.input_rate_hz, 1.0), out);
  put_u16(to_u16(caps.output_rate_hz, 1.0), out);
  end_frame(start, out);
}

void encode_sample(const DeviceSample& sample, uint16_t sequence, std::vector<uint8_t>* out) {
  const size_t start = begin_frame(kSample, out);
  put_u16(sequence, out);
  put_u32(static_cast<uint32_t>(sample.device_time_us), out);  // modulo 2^32
  put_u8(sample.has_palm_pose ? kSampleHasPalmPose : 0, out);
  for (double angle : sample.angles) put_i16(to_i16(angle, kAngleUnit, INT16_MIN), out);
  if (sample.has_palm_pose) {
    for (int i = 0; i < 3; ++i) put_u32(static_cast<uint32_t>(to_i32(sample.palm_position[i], kPositionUnit)), out);
    const glm::dquat& q = sample.palm_rotation;
    for (double c : {q.w, q.x, q.y, q.z}) put_i16(to_i16(c, 1.0 / kQuaternionScale, 0), out);
  }
  end_frame(start, out);
}

void encode_command(const DeviceCommand& command, uint32_t outputs, uint16_t sequence,
                    std::vector<uint8_t>* out) {
  outputs &= kKnownOutputs;
  const size_t start = begin_frame(kCommand, out);
  put_u16(sequence, out);
  put_u8(static_cast<uint8_t>(outputs), out);
  if (outputs & kOutputFingerResistance)
    for (double r : command.finger_resistance) put_u16(to_u16(r, kForceUnit), out);
  if (outputs & kOutputFingertipForce)
    for (const vec3& f : command.fingertip_force)
      for (int i = 0; i < 3; ++i) put_i16(to_i16(f[i], kForceUnit, 0), out);
  if (outputs & kOutputJointTorque)
    for (double t : command.joint_torque) put_i16(to_i16(t, kTorqueUnit, 0), out);
  end_frame(start, out);
}

void encode_heartbeat(std::vector<uint8_t>* out) {
  end_frame(begin_frame(kHeartbeat, out), out);
}

// ---- FrameReader

void FrameReader::reset() {
  size_ = 0;
  bad_left_ = 0;
}

void FrameReader::feed(const uint8_t* data, size_t size, Handler* handler) {
  while (size > 0) {
    if (size_ == 0) {
      // between frames: skip to the next sync byte
      const void* sync = std::memchr(data, kSync, size);
      const size_t skip = sync ? static_cast<size_t>(static_cast<const uint8_t*>(sync) - data) : size;
      consumed(skip, handler);
      data += skip;
      size -= skip;
      if (size == 0) return;
    }
    // take no more than the frame (or header) in the buffer needs
    const size_t want = size_ < kHeaderSize ? kHeaderSize : kHeaderSize + buffer_[2] + kCrcSize;
    const size_t n = std::min(want - size_, size);
    std::memcpy(buffer_.data() + size_, data, n);
    size_ += n;
    data += n;
    size -= n;
    parse(handler);
  }
}

void FrameReader::parse(Handler* handler) {
  while (size_ >= kHeaderSize) {
    const uint8_t type = buffer_[1];
    const size_t length = buffer_[2];
    if (length > kMaxPayload || length < min_payload(type)) {
      reject(kHeaderSize, handler);
      continue;
    }
    const size_t frame = kHeaderSize + length + kCrcSize;
    if (size_ < frame) return;
    if (crc16(buffer_.data() + 1, length + 2) != get_u16(buffer_.data() + frame - kCrcSize)) {
      reject(frame, handler);
      continue;
    }
    if (bad_left_ > 0) {
      // this frame began inside the bad one: the bad one was cut short by it
      bad_left_ = 0;
      handler->on_bad_frame(FrameFault::kTruncated);
    }
    handler->on_frame(static_cast<MessageType>(type), buffer_.data() + kHeaderSize, length);
    drop(frame, handler);
  }
}

void FrameReader::reject(size_t span, Handler* handler) {
  // a sync byte inside a pending bad frame's span is that frame's data, not another fault
  if (bad_left_ == 0) bad_left_ = span;
  drop(1, handler);
}

void FrameReader::drop(size_t count, Handler* handler) {
  std::memmove(buffer_.data(), buffer_.data() + count, size_ - count);
  size_ -= count;
  consumed(count, handler);
  const void* sync = std::memchr(buffer_.data(), kSync, size_);
  const size_t skip =
      sync ? static_cast<size_t>(static_cast<const uint8_t*>(sync) - buffer_.data()) : size_;
  if (skip == 0) return;
  std::memmove(buffer_.data(), buffer_.data() + skip, size_ - skip);
  size_ -= skip;
  consumed(skip, handler);
}

void FrameReader::consumed(size_t count, Handler* handler) {
  if (bad_left_ == 0) return;
  if (count < bad_left_) {
    bad_left_ -= count;
    return;
  }
  // scanned past the bad frame's end without a good frame starting inside it
  bad_left_ = 0;
  handler->on_bad_frame(FrameFault::kCorrupt);
}

// ---- the glove's side

void GloveSideDecoder::feed(const uint8_t* data, size_t size, HostSink* sink) {
  sink_ = sink;
  reader_.feed(data, size, this);
  sink_ = nullptr;
}

void GloveSideDecoder::on_frame(MessageType type, const uint8_t* payload, size_t size) {
  switch (type) {
    case kHello: {
      Hello hello;
      hello.version = get_u16(payload);
      hello.sample_rate_hz = get_u16(payload + 2);
      hello.command_rate_hz = get_u16(payload + 4);
      sink_->on_hello(hello);
      return;
    }
    case kCommand: {
      command_.sequence = get_u16(payload);
      command_.outputs = payload[2] & kKnownOutputs;
      if (size < command_size(command_.outputs)) {
        sink_->on_fault(FrameFault::kCorrupt);
        return;
      }
      command_.command = DeviceCommand{};
      const uint8_t* p = payload + kCommandSize;
      if (command_.outputs & kOutputFingerResistance)
        for (double& r : command_.command.finger_resistance) {
          r = get_u16(p) * kForceUnit;
          p += 2;
        }
      if (command_.outputs & kOutputFingertipForce)
        for (vec3& f : command_.command.fingertip_force)
          for (int i = 0; i < 3; ++i) {
            f[i] = get_i16(p) * kForceUnit;
            p += 2;
          }
      if (command_.outputs & kOutputJointTorque)
        for (double& t : command_.command.joint_torque) {
          t = get_i16(p) * kTorqueUnit;
          p += 2;
        }
      sink_->on_command(command_);
      return;
    }
    case kHeartbeat: sink_->on_heartbeat(); return;
    case kCaps:
    case kSample: sink_->on_fault(FrameFault::kCorrupt); return;  // the glove's own kind
  }
}

void GloveSideDecoder::on_bad_frame(FrameFault fault) { sink_->on_fault(fault); }

}  // namespace binary_profile

// ---- the host's side

namespace {

FrameFault to_fault(binary_profile::Verdict verdict) {
  return verdict == binary_profile::Verdict::kCorrupt ? FrameFault::kCorrupt
                                                      : FrameFault::kOutOfRange;
}

}  // namespace

FrustaProtocol::FrustaProtocol(uint16_t sample_rate_hz, uint16_t command_rate_hz) {
  hello_.sample_rate_hz = sample_rate_hz;
  hello_.command_rate_hz = command_rate_hz;
}

DeviceCapabilities FrustaProtocol::default_capabilities() const {
  // until CAPS: brakes only, at a rate any link carries (18-byte commands and 52-byte
  // samples at 100 Hz fit 115200 baud)
  DeviceCapabilities caps;
  caps.outputs = kOutputFingerResistance;
  caps.input_rate_hz = 100.0;
  caps.output_rate_hz = 100.0;
  return caps;
}

void FrustaProtocol::start(std::vector<uint8_t>* out) {
  reader_.reset();
  caps_received_ = false;
  command_sequence_ = 0;
  has_time_ = false;
  time_base_ = 0;
  sequence_base_ = 0;
  binary_profile::encode_hello(hello_, out);
}

void FrustaProtocol::feed(const uint8_t* data, size_t size, ProtocolSink* sink) {
  sink_ = sink;
  reader_.feed(data, size, this);
  sink_ = nullptr;
}

void FrustaProtocol::encode(const DeviceCommand& command, const DeviceCapabilities& capabilities,
                            std::vector<uint8_t>* out) {
  const uint32_t outputs = capabilities.outputs & binary_profile::kKnownOutputs;
  if (outputs == 0) return;  // nothing to render: the heartbeats keep the link
  binary_profile::encode_command(command, outputs, command_sequence_++, out);
}

void FrustaProtocol::encode_heartbeat(std::vector<uint8_t>* out) {
  // the handshake is retried at the heartbeat period until the glove answers
  if (caps_received_)
    binary_profile::encode_heartbeat(out);
  else
    binary_profile::encode_hello(hello_, out);
}

void FrustaProtocol::on_frame(binary_profile::MessageType type, const uint8_t* payload,
                              size_t size) {
  switch (type) {
    case binary_profile::kCaps: {
      DeviceCapabilities caps;
      const binary_profile::Verdict verdict = binary_profile::decode_caps(payload, &caps);
      if (verdict != binary_profile::Verdict::kGood) {
        sink_->on_fault(to_fault(verdict));
        return;
      }
      caps_received_ = true;
      sink_->on_capabilities(caps);
      return;
    }
    case binary_profile::kSample: {
      uint32_t time = 0;
      const binary_profile::Verdict verdict =
          binary_profile::decode_sample(payload, size, &sample_, &time);
      if (verdict != binary_profile::Verdict::kGood) {
        sink_->on_fault(to_fault(verdict));
        return;
      }
      // unwrap the glove's 32-bit microsecond clock (71.6 minutes a turn) and its sample
      // sequence (65536 samples a turn), so rates come from its clock and count
      const uint16_t sequence = static_cast<uint16_t>(payload[0] | payload[1] << 8);
      if (has_time_ && time < last_time_) time_base_ += int64_t{1} << 32;
      if (has_time_ && sequence < last_sequence_) sequence_base_ += int64_t{1} << 16;
      has_time_ = true;
      last_time_ = time;
      last_sequence_ = sequence;
      sample_.device_time_us = time_base_ + time;
      sample_.sequence = sequence_base_ + sequence;
      sink_->on_sample(sample_);
      return;
    }
    case binary_profile::kHeartbeat: sink_->on_heartbeat(); return;
    case binary_profile::kHello:
    case binary_profile::kCommand: sink_->on_fault(FrameFault::kCorrupt); return;  // our own kind
  }
}

void FrustaProtocol::on_bad_frame(FrameFault fault) { sink_->on_fault(fault); }

}  // namespace frusta
