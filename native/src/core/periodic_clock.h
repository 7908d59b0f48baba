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
//
// The ticks may be aligned to events (align): a glove's samples arrive on their own
// clock, and a sample that just missed a tick waits a whole period for the next; ticks
// that fall a little after the samples answer each within a fraction of one. A tick may
// also come early on an event (wait with a Wakeup): from a window before its deadline
// on, a signal runs it at once, so a sample is answered when it lands, and one that
// comes late still finds its tick waiting.
#pragma once

#include <chrono>
#include <cstdint>

#include "core/wakeup.h"

namespace frusta {

// Now on the steady clock, in nanoseconds: how threads stamp what they hand each other.
inline int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// How far to move a deadline `error` after the point it should fall on (modulo the
// period) so the ticks come to fall there over a few dozen ticks without a jump: an
// eighth of the error wrapped into (-period/2, period/2], at most a fiftieth of a period
// a tick (the ticks run within 2 % of their rate meanwhile; the steps' time does not).
std::chrono::steady_clock::duration phase_correction(std::chrono::steady_clock::duration error,
                                                     std::chrono::steady_clock::duration period);

class PeriodicClock {
 public:
  using Clock = std::chrono::steady_clock;

  // period: e.g. 1 ms; spin: how long before each deadline to stop sleeping and spin
  PeriodicClock(Clock::duration period, Clock::duration spin, int64_t max_burst = 10);

  // Restart the schedule: the first deadline is one period from now.
  void start();

  // Wait for the next deadline (none if it is past). Returns how late the wake-up
  // was; tick() is then the deadline this wake-up answers.
  Clock::duration wait() { return wait(nullptr, Clock::duration::zero()); }
  // The same, but a signal on `early` from `window` before the deadline on ends the wait
  // at once (a signal that came before the window is dropped as it opens; one that came
  // while the caller was away after the window opened stands). tick() is still the
  // deadline the tick answers, and an early tick counts as on time (0). Without a Wakeup
  // that is open, wait() exactly.
  Clock::duration wait(const Wakeup* early, Clock::duration window);

  // Move the coming deadlines, a little a tick, towards `when` plus whole periods; the
  // newest call wins.
  void align(Clock::time_point when) {
    anchor_ = when;
    aligned_ = true;
  }

  Clock::time_point tick() const { return tick_; }
  Clock::time_point deadline() const { return deadline_; }
  // ticks that ran more than a period late (caught up), and ticks dropped outright
  int64_t late() const { return late_; }
  int64_t dropped() const { return dropped_; }
  int64_t missed() const { return late_ + dropped_; }

 private:
  Clock::duration period_, spin_;
  int64_t max_burst_;
  Clock::time_point deadline_{}, tick_{}, anchor_{};
  bool aligned_ = false;
  int64_t late_ = 0, dropped_ = 0;
};

}  // namespace frusta
