// SPDX-License-Identifier: MIT
#include "scenes/simulated_glove.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/thread_priority.h"

namespace frusta::scenes {

namespace {

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

SimulatedGlove::SimulatedGlove(std::string path, double rate_hz, Firmware firmware,
                               Listener listener)
    : path_(std::move(path)),
      rate_hz_(rate_hz),
      firmware_(std::move(firmware)),
      listener_(std::move(listener)) {
  plug_in();
}

SimulatedGlove::~SimulatedGlove() {
  unplug();
  std::remove(path_.c_str());
}

void SimulatedGlove::open_pty() {
  const int master = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0)
    throw std::runtime_error("no pseudo-terminal");
  termios tty{};
  tcgetattr(master, &tty);
  cfmakeraw(&tty);  // bytes through untouched, both ways
  tcsetattr(master, TCSANOW, &tty);
  const std::string slave = ptsname(master);
  std::remove(path_.c_str());
  if (symlink(slave.c_str(), path_.c_str()) != 0) throw std::runtime_error("no symlink " + path_);
  master_ = master;
}

void SimulatedGlove::plug_in() {
  if (master_ >= 0) return;
  open_pty();
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void SimulatedGlove::unplug() {
  if (master_ < 0) return;
  stop_ = true;
  thread_.join();
  std::remove(path_.c_str());
  close(master_);
  master_ = -1;
}

void SimulatedGlove::set_rate(double rate_hz) { rate_hz_ = rate_hz; }
void SimulatedGlove::set_sending(bool sending) {
  std::lock_guard<std::mutex> lock(write_mutex_);  // waits out a frame being written
  sending_ = sending;
}

void SimulatedGlove::write_raw(const std::string& bytes) {
  std::lock_guard<std::mutex> lock(write_mutex_);
  if (master_ >= 0 && write(master_, bytes.data(), bytes.size()) < 0) std::perror("glove write");
}

void SimulatedGlove::run() {
  raise_to_realtime_priority();  // a glove's firmware does not share this machine's cores
  int64_t next = now_ns();
  int64_t tick = 0;
  char buffer[4096];
  while (!stop_) {
    const int64_t now = now_ns();
    if (now >= next) {
      {
        std::lock_guard<std::mutex> lock(write_mutex_);
        if (sending_) {
          const std::string frame = firmware_(tick++);
          if (write(master_, frame.data(), frame.size()) == static_cast<ssize_t>(frame.size()))
            ++frames_sent_;
        }
      }
      next += static_cast<int64_t>(1e9 / rate_hz_.load());
      if (next < now) next = now;
      continue;
    }
    pollfd p{master_, POLLIN, 0};
    const timespec wait{0, static_cast<long>(std::min<int64_t>(next - now, 999999999))};
    if (ppoll(&p, 1, &wait, nullptr) <= 0) continue;
    const ssize_t n = (p.revents & POLLIN) ? read(master_, buffer, sizeof buffer) : -1;
    if (n > 0) {
      Chunk chunk{now_ns(), std::string(buffer, static_cast<size_t>(n))};
      if (listener_) listener_(chunk.bytes);
      std::lock_guard<std::mutex> lock(received_mutex_);
      received_.push_back(std::move(chunk));
    } else {
      // nobody has the slave open (the engine closed it): nothing to read until the tick
      std::this_thread::sleep_for(std::chrono::nanoseconds(next - now));
    }
  }
}

std::string SimulatedGlove::received() const {
  std::lock_guard<std::mutex> lock(received_mutex_);
  std::string all;
  for (const Chunk& c : received_) all += c.bytes;
  return all;
}

std::vector<SimulatedGlove::Chunk> SimulatedGlove::chunks() const {
  std::lock_guard<std::mutex> lock(received_mutex_);
  return received_;
}

void SimulatedGlove::clear_received() {
  std::lock_guard<std::mutex> lock(received_mutex_);
  received_.clear();
}

}  // namespace frusta::scenes
