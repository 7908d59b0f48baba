// SPDX-License-Identifier: MIT
#include "devices/serial_stream.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "core/error.h"

namespace frusta {

namespace {

// one case per kSerialBauds entry
speed_t to_speed(int32_t baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 500000: return B500000;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 2000000: return B2000000;
    default: return B0;
  }
}

}  // namespace

SerialStream::SerialStream(std::string path, int32_t baud)
    : path_(std::move(path)), baud_(baud), name_("serial " + path_) {}

SerialStream::~SerialStream() { close(); }

frusta_result SerialStream::open() {
  close();
  const speed_t speed = to_speed(baud_);
  if (speed == B0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: baud %d is not a rate termios supports",
                name_.c_str(), baud_);
  const int fd = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail(FRUSTA_ERROR_IO, "%s: cannot open: %s", name_.c_str(), std::strerror(errno));
  termios tty{};
  if (tcgetattr(fd, &tty) != 0) {
    const int error = errno;
    ::close(fd);
    return fail(FRUSTA_ERROR_IO, "%s: not a serial port: %s", name_.c_str(), std::strerror(error));
  }
  cfmakeraw(&tty);
  tty.c_cflag |= CLOCAL | CREAD;
  tty.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  tty.c_cc[VMIN] = 0;
  tty.c_cc[VTIME] = 0;
  cfsetispeed(&tty, speed);
  cfsetospeed(&tty, speed);
  if (tcsetattr(fd, TCSANOW, &tty) != 0) {
    const int error = errno;
    ::close(fd);
    return fail(FRUSTA_ERROR_IO, "%s: cannot set raw %d baud: %s", name_.c_str(), baud_,
                std::strerror(error));
  }
  fd_ = fd;
  return FRUSTA_OK;
}

bool SerialStream::is_open() const { return fd_ >= 0; }

void SerialStream::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

IoStatus SerialStream::read(uint8_t* buffer, size_t capacity, int64_t timeout_us,
                            size_t* received) {
  *received = 0;
  if (fd_ < 0) return IoStatus::kDisconnected;
  // the glove's bytes, or the world's step (the command that answers them is due)
  pollfd p[2] = {{fd_, POLLIN, 0}, {wakeup_ ? wakeup_->handle() : -1, POLLIN, 0}};
  const timespec timeout{static_cast<time_t>(timeout_us / 1000000),
                         static_cast<long>(timeout_us % 1000000) * 1000};
  const int ready = ppoll(p, wakeup_ ? 2 : 1, &timeout, nullptr);
  if (ready < 0) return errno == EINTR ? IoStatus::kOk : IoStatus::kDisconnected;
  if (ready == 0) return IoStatus::kOk;
  if (wakeup_ && p[1].revents != 0) wakeup_->drain();
  if (p[0].revents == 0) return IoStatus::kOk;
  const ssize_t n = ::read(fd_, buffer, capacity);
  if (n > 0) {
    *received = static_cast<size_t>(n);
    return IoStatus::kOk;
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return IoStatus::kOk;
  // poll said readable and nothing came (a hang-up), or the port failed (EIO when the
  // glove is unplugged or the other end of a pty closes)
  return IoStatus::kDisconnected;
}

bool SerialStream::wakes_on(const Wakeup* wakeup) {
  wakeup_ = wakeup && wakeup->is_open() ? wakeup : nullptr;
  return wakeup_ != nullptr;
}

IoStatus SerialStream::write(const uint8_t* data, size_t size, bool* dropped) {
  *dropped = false;
  if (fd_ < 0) return IoStatus::kDisconnected;
  const ssize_t n = ::write(fd_, data, size);
  if (n == static_cast<ssize_t>(size)) return IoStatus::kOk;
  if (n >= 0 || errno == EAGAIN || errno == EINTR) {
    // the glove is not draining its input: a partial command is what it gets now, and
    // the next full one resynchronises it (both protocols frame by line or sync byte)
    *dropped = true;
    return IoStatus::kOk;
  }
  return IoStatus::kDisconnected;
}

}  // namespace frusta
