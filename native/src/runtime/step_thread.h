// SPDX-License-Identifier: MIT
// The world's own thread: steps on absolute deadlines at a rate (sleep, then spin the
// last part of each period for an on-time wake), catching up a short stall tick by
// tick and dropping a long one (core/periodic_clock.h). It keeps how late each tick
// woke, how many it lost, and the rate it achieved, for the step it runs to publish.
//
// A glove's samples come on its own clock. While a step says when they come, the ticks
// follow them: their deadlines move to half a period after the samples (PeriodicClock::
// align), and from a fifth of a period before a sample is due the glove's signal runs
// the tick at once. A sample is answered as it lands, and one up to half a period late
// still finds its tick waiting instead of waiting a whole period for the next.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

#include "core/base.h"
#include "core/step_histogram.h"
#include "core/wakeup.h"

namespace frusta {

class StepThread {
 public:
  // What a tick runs: the period in seconds and the tick's time (steady clock, ns); it
  // returns when a glove's newest sample came (steady clock, ns), which the coming ticks
  // follow, or 0 for none.
  using Step = std::function<int64_t(double dt, int64_t tick_ns)>;

  StepThread() = default;
  StepThread(const StepThread&) = delete;
  StepThread& operator=(const StepThread&) = delete;
  ~StepThread() { stop(); }

  // Host: start ticking (rate 1..100000 Hz, spin 0..one period, checked here);
  // FRUSTA_ERROR_WRONG_STATE if running. sample_arrived (may be null; it must outlive
  // the thread): signalled by a glove's thread as it sets a sample. realtime: the
  // thread asks for real-time priority (core/thread_priority.h).
  frusta_result start(double rate_hz, double spin_us, Step step, const Wakeup* sample_arrived = nullptr,
                      bool realtime = false);
  // Host: stop and join; returns once the current tick is done. No effect if stopped.
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }

  // The stepping thread (inside a tick): its own figures so far.
  const StepHistogram& lateness() const { return lateness_; }  // wake-up, microseconds
  int64_t overruns() const { return overruns_; }
  double achieved_rate_hz() const { return achieved_rate_hz_; }
  bool realtime() const { return realtime_; }  // the system granted it

 private:
  // a tick follows a glove's signal from 7/10 of a period before its deadline, which
  // falls half a period after the sample is due: a fifth of a period's early arrival
  static constexpr int kEarlyWindowTenths = 7;
  void run(double rate_hz, double spin_us, const Step& step, const Wakeup* sample_arrived, bool realtime);

  StepHistogram lateness_;
  int64_t overruns_ = 0;
  double achieved_rate_hz_ = 0.0;
  bool realtime_ = false;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace frusta
