// SPDX-License-Identifier: MIT
// Frusta's binary profile (binary_profile.md): framed little-endian messages with a
// CRC, for gloves faster than a text line allows. Both ends live here: FrustaProtocol
// is the host's, and binary_profile's encoders and GloveSideDecoder are the glove's
// (for the tests, the simulated glove, and a glove maker to copy).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "devices/glove_protocol.h"

namespace frusta {

namespace binary_profile {

constexpr uint8_t kSync = 0xF5;
constexpr uint16_t kVersion = 0x0100;  // major 1 (high byte), minor 0
constexpr size_t kHeaderSize = 3;      // sync, type, payload length
constexpr size_t kCrcSize = 2;
// the largest 1.0 payload is an 83-byte COMMAND; the rest leaves minor versions room
constexpr size_t kMaxPayload = 120;
constexpr size_t kMaxFrame = kHeaderSize + kMaxPayload + kCrcSize;

enum MessageType : uint8_t {
  kHello = 0x01,      // host -> glove
  kCaps = 0x02,       // glove -> host
  kSample = 0x03,     // glove -> host
  kCommand = 0x04,    // host -> glove
  kHeartbeat = 0x05,  // both ways
};

// the smallest payload of each type in version 1.0 (a minor version may append fields)
constexpr size_t kHelloSize = 6;
constexpr size_t kCapsSize = 16;
constexpr size_t kSampleSize = 47;  // without the palm pose
constexpr size_t kPalmPoseSize = 20;
constexpr size_t kCommandSize = 3;  // sequence and outputs, before the output blocks
constexpr size_t kResistanceBlockSize = 2 * FRUSTA_FINGER_COUNT;
constexpr size_t kForceBlockSize = 6 * FRUSTA_FINGER_COUNT;
constexpr size_t kTorqueBlockSize = 2 * FRUSTA_HAND_JOINT_COUNT;

constexpr uint8_t kSampleHasPalmPose = 1u << 0;  // SAMPLE flags
constexpr uint8_t kCapsHasPalmPose = 1u << 0;    // CAPS flags
constexpr uint32_t kKnownOutputs =
    kOutputFingerResistance | kOutputFingertipForce | kOutputJointTorque;

// wire units and the ranges the host accepts
constexpr double kAngleUnit = 1e-4;        // radians per count
constexpr int32_t kMaxAngleCounts = 31416;  // pi: beyond it no joint of a hand
constexpr double kPositionUnit = 1e-5;     // metres per count
constexpr int32_t kMaxPositionCounts = 100000000;  // 1 km from the tracking origin
constexpr double kQuaternionScale = 32767.0;  // counts per unit component
constexpr double kMaxQuaternionNormError = 0.01;
constexpr double kForceUnit = 0.01;   // newtons per count
constexpr double kTorqueUnit = 1e-4;  // newton-metres per count

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial 0xFFFF, no reflection, no final xor.
uint16_t crc16(const uint8_t* data, size_t size);

// What a HELLO carries besides the version.
struct Hello {
  uint16_t version = kVersion;
  uint16_t sample_rate_hz = 0;   // SAMPLEs per second the host asks for; 0: the glove's own
  uint16_t command_rate_hz = 0;  // COMMANDs per second the host means to send; 0: not said
};

// A COMMAND as the glove reads it.
struct Command {
  uint16_t sequence = 0;
  uint32_t outputs = 0;  // DeviceOutput bits whose blocks it carried
  DeviceCommand command;
};

// Each appends one whole frame to `out`. Values are rounded to the wire's units and
// clamped to what the field can hold; a NaN angle or position goes out as the field's
// most negative value, which the host rejects. caps.protocol_version 0 means kVersion.
void encode_hello(const Hello& hello, std::vector<uint8_t>* out);
void encode_caps(const DeviceCapabilities& caps, std::vector<uint8_t>* out);
void encode_sample(const DeviceSample& sample, uint16_t sequence, std::vector<uint8_t>* out);
// Only the blocks of `outputs` (DeviceOutput bits) are sent; NaN forces go out as zero.
void encode_command(const DeviceCommand& command, uint32_t outputs, uint16_t sequence,
                    std::vector<uint8_t>* out);
void encode_heartbeat(std::vector<uint8_t>* out);

// Splits a byte stream into frames whose CRC holds, in any chunking, with a buffer of
// one frame. After a bad frame it resumes at the next sync byte after the bad one's,
// so a frame hidden in the bad one's bytes is still found. A bad frame is reported
// once: kTruncated when a good frame starts inside its claimed span (a new frame cut
// it short), else kCorrupt. Bytes outside frames are skipped without a report.
class FrameReader {
 public:
  class Handler {
   public:
    virtual ~Handler() = default;
    // Type known, length at least the type's minimum, CRC good.
    virtual void on_frame(MessageType type, const uint8_t* payload, size_t size) = 0;
    virtual void on_bad_frame(FrameFault fault) = 0;
  };

  void reset();
  void feed(const uint8_t* data, size_t size, Handler* handler);

 private:
  void parse(Handler* handler);
  void reject(size_t span, Handler* handler);
  void drop(size_t count, Handler* handler);  // from the front, then on to a sync byte
  void consumed(size_t count, Handler* handler);

  std::array<uint8_t, kMaxFrame> buffer_{};
  size_t size_ = 0;       // buffer_[0] is a sync byte when size_ > 0
  size_t bad_left_ = 0;   // bytes until the pending bad frame's span ends (0: none)
};

// What a glove hears from the host.
class HostSink {
 public:
  virtual ~HostSink() = default;
  virtual void on_hello(const Hello& hello) = 0;
  virtual void on_command(const Command& command) = 0;
  virtual void on_heartbeat() = 0;
  virtual void on_fault(FrameFault fault) = 0;
};

// The glove's decoder of HELLO, COMMAND and HEARTBEAT frames.
class GloveSideDecoder final : private FrameReader::Handler {
 public:
  void reset() { reader_.reset(); }
  void feed(const uint8_t* data, size_t size, HostSink* sink);

 private:
  void on_frame(MessageType type, const uint8_t* payload, size_t size) override;
  void on_bad_frame(FrameFault fault) override;

  FrameReader reader_;
  HostSink* sink_ = nullptr;  // during feed
  Command command_;
};

}  // namespace binary_profile

// The host's side: HELLO on start and every heartbeat until CAPS arrives, then
// HEARTBEATs; SAMPLEs to DeviceSamples (checked against the ranges above); commands
// with the blocks of the outputs the glove announced.
class FrustaProtocol final : public GloveProtocol, private binary_profile::FrameReader::Handler {
 public:
  // The rates go in the HELLO (0: let the glove choose / not said).
  explicit FrustaProtocol(uint16_t sample_rate_hz = 0, uint16_t command_rate_hz = 0);

  DeviceCapabilities default_capabilities() const override;
  void start(std::vector<uint8_t>* out) override;
  void feed(const uint8_t* data, size_t size, ProtocolSink* sink) override;
  void encode(const DeviceCommand& command, const DeviceCapabilities& capabilities,
              std::vector<uint8_t>* out) override;
  void encode_heartbeat(std::vector<uint8_t>* out) override;

 private:
  void on_frame(binary_profile::MessageType type, const uint8_t* payload, size_t size) override;
  void on_bad_frame(FrameFault fault) override;

  binary_profile::Hello hello_;
  binary_profile::FrameReader reader_;
  ProtocolSink* sink_ = nullptr;  // during feed
  bool caps_received_ = false;
  uint16_t command_sequence_ = 0;
  // the glove's 32-bit microsecond clock and 16-bit sample sequence, unwrapped
  bool has_time_ = false;
  uint32_t last_time_ = 0;
  int64_t time_base_ = 0;
  uint16_t last_sequence_ = 0;
  int64_t sequence_base_ = 0;
  DeviceSample sample_;
};

}  // namespace frusta
