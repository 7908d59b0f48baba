// SPDX-License-Identifier: MIT
#include "core/wakeup.h"

#if defined(__linux__)
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>
#elif !defined(_WIN32)
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>
#endif

#include <cstdint>

namespace frusta {

Wakeup::~Wakeup() {
#if !defined(_WIN32)
  if (read_fd_ >= 0) ::close(read_fd_);
  if (write_fd_ >= 0 && write_fd_ != read_fd_) ::close(write_fd_);
#endif
}

bool Wakeup::open() {
  if (is_open()) return true;
#if defined(__linux__)
  const int fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (fd < 0) return false;
  read_fd_ = write_fd_ = fd;
  return true;
#elif !defined(_WIN32)
  int fds[2];
  if (pipe(fds) != 0) return false;
  for (int fd : fds) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
  read_fd_ = fds[0];
  write_fd_ = fds[1];
  return true;
#else
  return false;
#endif
}

void Wakeup::signal() const {
#if !defined(_WIN32)
  if (write_fd_ < 0) return;
  // a full counter or pipe already holds a wake-up: the write may fail, harmlessly
  const uint64_t one = 1;
  const auto written = ::write(write_fd_, &one, write_fd_ == read_fd_ ? sizeof one : 1);
  (void)written;
#endif
}

void Wakeup::drain() const {
#if !defined(_WIN32)
  if (read_fd_ < 0) return;
  uint64_t bytes[8];
  while (::read(read_fd_, bytes, sizeof bytes) > 0 && read_fd_ != write_fd_) {
  }
#endif
}

bool Wakeup::wait_until(std::chrono::steady_clock::time_point until) const {
#if !defined(_WIN32)
  if (read_fd_ < 0) return false;
  const auto left = until - std::chrono::steady_clock::now();
  const int64_t ns = left.count() > 0 ? std::chrono::duration_cast<std::chrono::nanoseconds>(left).count() : 0;
  pollfd p{read_fd_, POLLIN, 0};
  const timespec timeout{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  // an interrupted wait counts as no signal: the caller's schedule goes on
  if (ppoll(&p, 1, &timeout, nullptr) <= 0 || p.revents == 0) return false;
  drain();
  return true;
#else
  (void)until;
  return false;
#endif
}

}  // namespace frusta
