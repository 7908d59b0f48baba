// SPDX-License-Identifier: MIT
// The schedule's logic, not its timing (timings belong in tools/bench runtime).
#include "runtime/periodic_clock.h"

#include <gtest/gtest.h>

#include <thread>

namespace frusta {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;

TEST(PeriodicClock, DeadlinesAreAbsoluteSoLatenessDoesNotAccumulate) {
  PeriodicClock clock(milliseconds(1), microseconds(200));
  clock.start();
  const PeriodicClock::Clock::time_point first = clock.deadline();
  for (int i = 0; i < 20; ++i) {
    const PeriodicClock::Clock::duration late = clock.wait();
    EXPECT_GE(late.count(), 0) << "never wakes early";
  }
  // on the grid the first deadline set, whatever the lateness; a loaded machine may
  // have skipped whole ticks, which the clock counts
  EXPECT_EQ(clock.deadline(), first + (20 + clock.missed()) * milliseconds(1));
}

TEST(PeriodicClock, AStallSkipsTheLostTicksInsteadOfBursting) {
  PeriodicClock clock(milliseconds(1), microseconds(100));
  clock.start();
  clock.wait();
  std::this_thread::sleep_for(milliseconds(6));  // a stall of several periods
  clock.wait();
  EXPECT_GE(clock.missed(), 3);
  EXPECT_GT(clock.deadline(), PeriodicClock::Clock::now()) << "the next tick is ahead again";
}

}  // namespace
}  // namespace frusta
