// SPDX-License-Identifier: MIT
#include "runtime/periodic_clock.h"

#include <thread>

namespace frusta {

PeriodicClock::PeriodicClock(Clock::duration period, Clock::duration spin)
    : period_(period), spin_(spin) {}

void PeriodicClock::start() {
  deadline_ = Clock::now() + period_;
  missed_ = 0;
}

PeriodicClock::Clock::duration PeriodicClock::wait() {
  Clock::time_point now = Clock::now();
  if (now > deadline_ + period_) {
    // hopelessly behind: skip the lost ticks rather than burst through them
    const auto behind = (now - deadline_) / period_;
    missed_ += behind;
    deadline_ += behind * period_;
  }
  if (deadline_ - now > spin_) std::this_thread::sleep_until(deadline_ - spin_);
  while ((now = Clock::now()) < deadline_) {
  }
  const Clock::duration late = now - deadline_;
  deadline_ += period_;
  return late;
}

}  // namespace frusta
