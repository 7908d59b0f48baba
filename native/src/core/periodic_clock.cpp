// SPDX-License-Identifier: MIT
#include "core/periodic_clock.h"

#include <algorithm>
#include <thread>

namespace frusta {

using Clock = std::chrono::steady_clock;

PeriodicClock::PeriodicClock(Clock::duration period, Clock::duration spin, int64_t max_burst)
    : period_(period), spin_(spin), max_burst_(max_burst) {}

Clock::duration phase_correction(Clock::duration error, Clock::duration period) {
  if (period <= Clock::duration::zero()) return Clock::duration::zero();
  Clock::duration wrapped = error % period;  // (-period, period)
  if (wrapped > period / 2) wrapped -= period;
  if (wrapped <= -period / 2) wrapped += period;
  const Clock::duration most = period / 50;
  return -std::clamp<Clock::duration>(wrapped / 8, -most, most);
}

void PeriodicClock::start() {
  deadline_ = Clock::now() + period_;
  late_ = dropped_ = 0;
  aligned_ = false;
}

PeriodicClock::Clock::duration PeriodicClock::wait(const Wakeup* early, Clock::duration window) {
  if (aligned_) deadline_ += phase_correction(deadline_ - anchor_, period_);
  Clock::time_point now = Clock::now();
  const auto behind = (now - deadline_) / period_;
  if (behind > max_burst_) {
    // hopelessly behind: give up on all but the last burst's worth of ticks
    dropped_ += behind - max_burst_;
    deadline_ += (behind - max_burst_) * period_;
  }
  if (now > deadline_ + period_) ++late_;
  bool woken = false;
  if (early != nullptr && early->is_open() && deadline_ - now > spin_) {
    if (deadline_ - window > now) {
      // a signal from before the window answers an earlier tick: ticks that took it
      // would come a period ahead of their events, for good
      std::this_thread::sleep_until(deadline_ - window);
      early->drain();
    }
    woken = early->wait_until(deadline_ - spin_);
  }
  if (woken) {
    now = Clock::now();
  } else {
    if (deadline_ - Clock::now() > spin_) std::this_thread::sleep_until(deadline_ - spin_);
    while ((now = Clock::now()) < deadline_) {
    }
  }
  tick_ = deadline_;
  deadline_ += period_;
  return std::max(now - tick_, Clock::duration::zero());
}

}  // namespace frusta
