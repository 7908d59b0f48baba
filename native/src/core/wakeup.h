// SPDX-License-Identifier: MIT
// A nudge from the 1 kHz thread to a device thread that is waiting on its glove: the
// step publishes a hand's feed and signals; the device thread, blocked in its stream's
// read, wakes at once and sends the command that answers it, instead of on a schedule
// of its own (up to a period later). It is a kernel counter (Linux: an eventfd, other
// POSIX: a pipe) so that a stream can wait on it and on the glove together.
//
// The same nudge runs the other way: a glove's thread signals the world's thread when
// it sets a sample, and the tick that was waiting for it runs at once (wait_until).
//
// Threads: open() on the host, before the signalling thread can see the wakeup is in
// use (the port opens it before a device claims it); signal() from the signalling
// thread, one non-blocking write, never a wait; drain(), handle() and wait_until() from
// the waiting thread. Windows: not opened (its serial reads wait on COMMTIMEOUTS alone);
// the device thread then keeps its own schedule, and the world's thread its ticks.
#pragma once

#include <chrono>

namespace frusta {

class Wakeup {
 public:
  Wakeup() = default;
  ~Wakeup();
  Wakeup(const Wakeup&) = delete;
  Wakeup& operator=(const Wakeup&) = delete;

  // Host: make the counter (once; later calls keep it). False if the system has none to
  // give (out of descriptors): signal() then does nothing and waiters keep their
  // timeouts.
  bool open();
  bool is_open() const { return read_fd_ >= 0; }
  // Stepping thread: wake whoever waits on handle(). Never blocks; a signal nobody has
  // drained yet stands (signals do not pile up beyond one wake-up).
  void signal() const;
  // Waiting thread: the descriptor that turns readable on a signal (-1: not open), and
  // clear it after waking.
  int handle() const { return read_fd_; }
  void drain() const;
  // Waiting thread: block until a signal (true, drained) or `until` on the steady clock
  // (false). Not open: false at once, without waiting.
  bool wait_until(std::chrono::steady_clock::time_point until) const;

 private:
  int read_fd_ = -1, write_fd_ = -1;  // the same eventfd on Linux
};

}  // namespace frusta
