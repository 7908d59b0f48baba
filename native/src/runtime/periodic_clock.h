// SPDX-License-Identifier: MIT
// Ticks at a fixed rate on absolute deadlines, so a late tick does not shift the ones
// after it: sleep until shortly before the deadline (cheap, but the kernel wakes us a
// little late), then spin the rest (exact, but burns the core). The spin window is the
// knob between the two; tools/bench runtime measures what each costs.
#pragma once

#include <chrono>
#include <cstdint>

namespace frusta {

class PeriodicClock {
 public:
  using Clock = std::chrono::steady_clock;

  // period: e.g. 1 ms; spin: how long before each deadline to stop sleeping and spin
  PeriodicClock(Clock::duration period, Clock::duration spin);

  // Restart the schedule: the first deadline is one period from now.
  void start();

  // Wait for the next deadline. Returns how late the wake-up was. A tick that finds
  // its deadline already past does not wait; if it is more than a period behind, the
  // schedule skips ahead (counted as missed) instead of running a burst to catch up.
  Clock::duration wait();

  Clock::time_point deadline() const { return deadline_; }
  int64_t missed() const { return missed_; }

 private:
  Clock::duration period_, spin_;
  Clock::time_point deadline_{};
  int64_t missed_ = 0;
};

}  // namespace frusta
