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
  // on the grid the first deadline set, whatever the lateness: a late tick still
  // answers its own deadline; only ticks dropped after a long stall move past theirs
  EXPECT_EQ(clock.deadline(), first + (20 + clock.dropped()) * milliseconds(1));
}

TEST(PeriodicClock, AShortStallIsCaughtUpTickByTick) {
  // short: within the burst, which is made far longer than the stall, since a loaded
  // machine can stretch a 5 ms sleep past the default 10 periods (the ticks would be
  // dropped, as ALongStallDropsAllButOneBurst checks)
  PeriodicClock clock(milliseconds(1), microseconds(100), 1000);
  clock.start();
  clock.wait();
  const PeriodicClock::Clock::time_point before = clock.tick();
  std::this_thread::sleep_for(milliseconds(5));  // a stall of several periods
  // the lost ticks come back to back, each answering its own deadline
  int immediate = 0;
  while (clock.deadline() < PeriodicClock::Clock::now()) {
    clock.wait();
    ++immediate;
    EXPECT_EQ(clock.tick(), before + immediate * milliseconds(1));
  }
  EXPECT_GE(immediate, 3);
  EXPECT_GE(clock.late(), 3);
  EXPECT_EQ(clock.dropped(), 0);
}

TEST(PeriodicClock, ALongStallDropsAllButOneBurst) {
  PeriodicClock clock(milliseconds(1), microseconds(100), 4);
  clock.start();
  clock.wait();
  std::this_thread::sleep_for(milliseconds(20));
  clock.wait();
  EXPECT_GE(clock.dropped(), 10);
  int burst = 0;
  while (clock.deadline() < PeriodicClock::Clock::now()) {
    clock.wait();
    ++burst;
  }
  EXPECT_LE(burst, 5) << "at most max_burst ticks (and one that fell due meanwhile) run late";
}

}  // namespace
}  // namespace frusta
