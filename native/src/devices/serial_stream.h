// SPDX-License-Identifier: MIT
// A serial port: USB serial (/dev/ttyACM*, /dev/ttyUSB*, COM3), Bluetooth RFCOMM
// (/dev/rfcomm*, a Bluetooth COM port), or a pseudo-terminal (how the tests plug in a
// simulated glove). Raw 8N1, no flow control, DTR and RTS raised (boards that reset or
// wait on DTR start sending); the path is reopened on reconnect, so a stable name
// (/dev/serial/by-id/..., a symlink) follows the glove across replugs.
// POSIX termios in serial_stream_posix.cpp, the Win32 comm API in serial_stream_win32.cpp.
#pragma once

#include <cstdint>
#include <string>

#include "devices/byte_stream.h"

namespace frusta {

// The rates termios names (and Windows drivers take); anything else is refused.
inline constexpr int32_t kSerialBauds[] = {9600,   19200,  38400,   57600,   115200, 230400,
                                           460800, 500000, 921600, 1000000, 2000000};
constexpr bool is_supported_baud(int32_t baud) {
  for (const int32_t supported : kSerialBauds)
    if (baud == supported) return true;
  return false;
}

class SerialStream final : public ByteStream {
 public:
  SerialStream(std::string path, int32_t baud);
  ~SerialStream() override;

  frusta_result open() override;
  void close() override;
  bool is_open() const override;
  IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) override;
  IoStatus write(const uint8_t* data, size_t size, bool* dropped) override;
  const std::string& name() const override { return name_; }
#ifndef _WIN32
  bool wakes_on(const Wakeup* wakeup) override;
#endif

 private:
  std::string path_;
  int32_t baud_;
  std::string name_;
#ifdef _WIN32
  void* handle_ = nullptr;        // HANDLE
  uint32_t read_timeout_ms_ = 0;  // what the port's COMMTIMEOUTS hold now
#else
  int fd_ = -1;
  const Wakeup* wakeup_ = nullptr;  // open, or null
#endif
};

}  // namespace frusta
