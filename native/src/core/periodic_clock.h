// SPDX-License-Identifier: MIT
// Ticks at a fixed rate on absolute deadlines, so a late tick does not shift the ones
// after it: sleep until shortly before the deadline (cheap, but the kernel wakes us a
// little late), then spin the rest (exact, but burns the core). The spin window is the
// knob between the two; tools/bench runtime measures what each costs.
//
// A tick that finds its deadline past runs at once: after a short stall the ticks it
// lost run back to back until the schedule is caught up, so the world's time keeps
// pace with the glove's (a world that silently skipped ticks would see the hand move
// two ticks' worth in one, and kick what it holds). Only a stall longer than
// max_burst periods is given up on: those ticks are dropped.
#pragma once

#include <chrono>
#include <cstdint>

namespace frusta {

// Now on the steady clock, in nanoseconds: how threads stamp what they hand each other.
inline int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

class PeriodicClock {
 public:
  using Clock = std::chrono::steady_clock;

  // period: e.g. 1 ms; spin: how long before each deadline to stop sleeping and spin
  PeriodicClock(Clock::duration period, Clock::duration spin, int64_t max_burst = 10);

  // Restart the schedule: the first deadline is one period from now.
  void start();

  // Wait for the next deadline (none if it is past). Returns how late the wake-up
  // was; tick() is then the deadline this wake-up answers.
  Clock::duration wait();

  Clock::time_point tick() const { return tick_; }
  Clock::time_point deadline() const { return deadline_; }
  // ticks that ran more than a period late (caught up), and ticks dropped outright
  int64_t late() const { return late_; }
  int64_t dropped() const { return dropped_; }
  int64_t missed() const { return late_ + dropped_; }

 private:
  Clock::duration period_, spin_;
  int64_t max_burst_;
  Clock::time_point deadline_{}, tick_{};
  int64_t late_ = 0, dropped_ = 0;
};

}  // namespace frusta
