// SPDX-License-Identifier: MIT
#include "core/periodic_clock.h"

#include <thread>

namespace frusta {

PeriodicClock::PeriodicClock(Clock::duration period, Clock::duration spin, int64_t max_burst)
    : period_(period), spin_(spin), max_burst_(max_burst) {}

void PeriodicClock::start() {
  deadline_ = Clock::now() + period_;
  late_ = dropped_ = 0;
}

PeriodicClock::Clock::duration PeriodicClock::wait() {
  Clock::time_point now = Clock::now();
  const auto behind = (now - deadline_) / period_;
  if (behind > max_burst_) {
    // hopelessly behind: give up on all but the last burst's worth of ticks
    dropped_ += behind - max_burst_;
    deadline_ += (behind - max_burst_) * period_;
  }
  if (now > deadline_ + period_) ++late_;
  if (deadline_ - now > spin_) std::this_thread::sleep_until(deadline_ - spin_);
  while ((now = Clock::now()) < deadline_) {
  }
  tick_ = deadline_;
  deadline_ += period_;
  return now - tick_;
}

}  // namespace frusta
