// SPDX-License-Identifier: MIT
// A byte pipe to a glove: a serial port (USB serial, Bluetooth RFCOMM, a pseudo-
// terminal) or a HID device's reports. A device thread owns one; nothing else calls it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/base.h"
#include "core/wakeup.h"

namespace frusta {

enum class IoStatus {
  kOk,            // bytes moved (possibly none on a read that timed out)
  kDisconnected,  // the other end is gone: close, then open again to reconnect
};

class ByteStream {
 public:
  virtual ~ByteStream() = default;
  // Opens the device (again, after a disconnect). On failure the thread's error says
  // why, naming the device.
  virtual frusta_result open() = 0;
  virtual void close() = 0;
  virtual bool is_open() const = 0;
  // Waits at most timeout_us for bytes, then returns what came (*received may be 0).
  // A stream that wakes_on() a wakeup also returns early, with nothing, once it is
  // signalled (and drains it).
  virtual IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us,
                        size_t* received) = 0;
  // From now on read() returns when `wakeup` is signalled too, if this stream can wait
  // on it and on the glove together (a serial port on POSIX): true then. Others wait
  // their timeouts out, and the caller keeps a schedule of its own. Before the reads.
  virtual bool wakes_on(const Wakeup* wakeup) {
    (void)wakeup;
    return false;
  }
  // Writes all of data or reports the device gone. A device that cannot keep up
  // drops the command (counted by the caller), never blocks the thread.
  virtual IoStatus write(const uint8_t* data, size_t size, bool* dropped) = 0;
  // For messages: "serial /dev/ttyACM0".
  virtual const std::string& name() const = 0;
};

}  // namespace frusta
