// SPDX-License-Identifier: MIT
// A wire format between the engine and a glove: bytes in become samples (and the
// glove's capabilities), commands out become bytes. Stateless about the wire itself:
// the device thread moves the bytes, so one protocol runs over serial, HID or a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "devices/device_types.h"

namespace frusta {

// Why a frame was thrown away (counted per reason in the device's status).
enum class FrameFault {
  kCorrupt,     // bad checksum, bad syntax, unknown type
  kTruncated,   // cut short by the next frame's start or an overlong line
  kOutOfRange,  // well formed, but a value the glove cannot mean (NaN, beyond range)
};

// What a protocol reports while it decodes; called on the device thread.
class ProtocolSink {
 public:
  virtual ~ProtocolSink() = default;
  virtual void on_sample(const DeviceSample& sample) = 0;
  virtual void on_capabilities(const DeviceCapabilities& capabilities) = 0;
  virtual void on_fault(FrameFault fault) = 0;
  virtual void on_heartbeat() = 0;
};

class GloveProtocol {
 public:
  virtual ~GloveProtocol() = default;
  // The capabilities assumed until the glove announces its own (if it ever does).
  virtual DeviceCapabilities default_capabilities() const = 0;
  // After each (re)connect: forget partial frames; append what the glove must be sent
  // first (a handshake) to `out`.
  virtual void start(std::vector<uint8_t>* out) = 0;
  // Bytes from the glove, in order and in any chunks.
  virtual void feed(const uint8_t* data, size_t size, ProtocolSink* sink) = 0;
  // Append the bytes that tell the glove to render `command` (within `capabilities`).
  virtual void encode(const DeviceCommand& command, const DeviceCapabilities& capabilities,
                      std::vector<uint8_t>* out) = 0;
  // Append a keep-alive, sent when no command went out for a while (may append nothing).
  virtual void encode_heartbeat(std::vector<uint8_t>* out) = 0;
};

}  // namespace frusta
