// SPDX-License-Identifier: MIT
// A serial port through POSIX termios: USB serial (/dev/ttyACM*, /dev/ttyUSB*),
// Bluetooth RFCOMM (/dev/rfcomm*), or a pseudo-terminal (how the tests plug in a
// simulated glove). Raw 8N1, no flow control, non-blocking; the path is reopened on
// reconnect, so a stable name (/dev/serial/by-id/..., a symlink) follows the glove
// across replugs.
#pragma once

#include <string>

#include "devices/byte_stream.h"

namespace frusta {

// The baud rates termios names; anything else is refused.
bool is_supported_baud(int32_t baud);

class SerialStream final : public ByteStream {
 public:
  SerialStream(std::string path, int32_t baud);
  ~SerialStream() override;

  frusta_result open() override;
  void close() override;
  bool is_open() const override { return fd_ >= 0; }
  IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) override;
  IoStatus write(const uint8_t* data, size_t size, bool* dropped) override;
  const std::string& name() const override { return name_; }

 private:
  std::string path_;
  int32_t baud_;
  std::string name_;
  int fd_ = -1;
};

}  // namespace frusta
