// SPDX-License-Identifier: MIT
// The world's own thread: steps on absolute deadlines at a rate (sleep, then spin the
// last part of each period for an on-time wake), catching up a short stall tick by
// tick and dropping a long one (core/periodic_clock.h). It keeps how late each tick
// woke, how many it lost, and the rate it achieved, for the step it runs to publish.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

#include "core/base.h"
#include "core/step_histogram.h"

namespace frusta {

class StepThread {
 public:
  // What a tick runs: the period in seconds and the tick's time (steady clock, ns); it
  // returns a time (steady clock, ns) the coming ticks should fall on plus whole periods
  // (PeriodicClock::align), or 0 for none.
  using Step = std::function<int64_t(double dt, int64_t tick_ns)>;

  StepThread() = default;
  StepThread(const StepThread&) = delete;
  StepThread& operator=(const StepThread&) = delete;
  ~StepThread() { stop(); }

  // Host: start ticking (rate 1..100000 Hz, spin 0..one period, checked here);
  // FRUSTA_ERROR_WRONG_STATE if running.
  frusta_result start(double rate_hz, double spin_us, Step step);
  // Host: stop and join; returns once the current tick is done. No effect if stopped.
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }

  // The stepping thread (inside a tick): its own figures so far.
  const StepHistogram& lateness() const { return lateness_; }  // wake-up, microseconds
  int64_t overruns() const { return overruns_; }
  double achieved_rate_hz() const { return achieved_rate_hz_; }

 private:
  void run(double rate_hz, double spin_us, const Step& step);

  StepHistogram lateness_;
  int64_t overruns_ = 0;
  double achieved_rate_hz_ = 0.0;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace frusta
