// SPDX-License-Identifier: MIT
// The schedule's logic, not its timing (timings belong in tools/bench runtime).
#include "core/periodic_clock.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
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

TEST(PeriodicClock, AStallIsCaughtUpTickByTick) {
  // no burst limit, so nothing is dropped however long a loaded machine makes the 5 ms
  // sleep (ALongStallDropsAllButOneBurst checks the limit)
  PeriodicClock clock(milliseconds(1), microseconds(100), std::numeric_limits<int64_t>::max());
  clock.start();
  clock.wait();
  const PeriodicClock::Clock::time_point before = clock.tick();
  std::this_thread::sleep_for(milliseconds(5));  // a stall of at least 5 periods
  // the lost ticks come back to back, each answering its own deadline
  int immediate = 0;
  while (clock.deadline() < PeriodicClock::Clock::now()) {
    clock.wait();
    ++immediate;
    EXPECT_EQ(clock.tick(), before + immediate * milliseconds(1));
  }
  EXPECT_GE(immediate, 4) << "the deadlines 1 to 4 ms after the tick passed in the sleep";
  EXPECT_GE(clock.late(), 3) << "and those 1 to 3 ms after it ran a period or more late";
  EXPECT_EQ(clock.dropped(), 0);
}

TEST(PeriodicClock, ALongStallDropsAllButOneBurst) {
  using Clock = PeriodicClock::Clock;
  PeriodicClock clock(milliseconds(1), microseconds(100), 4);
  clock.start();
  clock.wait();
  std::this_thread::sleep_for(milliseconds(20));  // at least 19 periods past the deadline
  const Clock::time_point before = Clock::now();
  clock.wait();
  const Clock::time_point after = Clock::now();
  EXPECT_GE(clock.dropped(), 15) << "19 or more behind, all but a burst of 4 dropped";
  // the tick it runs answers a deadline 4 to 5 periods before its wake-up (whenever
  // that was), not the one 20 periods back: only a burst's worth is left to catch up
  EXPECT_GT(clock.tick(), before - 5 * milliseconds(1));
  EXPECT_LE(clock.tick(), after - 4 * milliseconds(1));
}

// A tick may come early on a Wakeup's signal, but only within its window: the deadlines
// stay on their grid either way. Periods are long so that nothing here depends on how
// soon a thread is scheduled (a machine that stalls for seconds could only make it pass
// late). Windows has no Wakeup: its threads keep their own schedules.
class PeriodicClockWakeup : public ::testing::Test {
 protected:
  using Clock = PeriodicClock::Clock;
  void SetUp() override {
#ifdef _WIN32
    GTEST_SKIP() << "no Wakeup on Windows";
#endif
    ASSERT_TRUE(early.open());
  }
  Wakeup early;
};

TEST_F(PeriodicClockWakeup, ASignalWithinTheWindowRunsTheTickAtOnceOnItsDeadline) {
  PeriodicClock clock(std::chrono::seconds(30), microseconds(200));
  clock.start();
  const Clock::time_point first = clock.deadline();
  early.signal();  // a sample already there when the wait begins, in the window
  EXPECT_EQ(clock.wait(&early, std::chrono::seconds(30)), Clock::duration::zero()) << "on time";
  EXPECT_LT(Clock::now(), first) << "ran at once, not at its deadline";
  EXPECT_EQ(clock.tick(), first) << "the tick still answers its deadline";
  EXPECT_EQ(clock.deadline(), first + std::chrono::seconds(30));
  // a signal that comes while the tick waits: tools/bench devices (a glove's sample to
  // its step, 45-75 us p50); a second thread in this file hung under qemu-aarch64,
  // where tools/test runs it
}

// A signal that came before the window answered an earlier tick: taken, the ticks would
// come a period ahead of their samples from then on.
TEST_F(PeriodicClockWakeup, ASignalFromBeforeTheWindowIsDroppedAsItOpens) {
  PeriodicClock clock(milliseconds(300), microseconds(0));
  clock.start();
  early.signal();
  clock.wait(&early, milliseconds(50));
  EXPECT_GE(Clock::now(), clock.tick()) << "waited for its deadline";
  // without a Wakeup, or with one that is not open, wait() as ever
  Wakeup closed;
  clock.wait(&closed, milliseconds(300));
  EXPECT_GE(Clock::now(), clock.tick());
}

// The alignment's rule alone: a fraction of the phase error, wrapped to the nearer
// tick, bounded per tick.
TEST(PeriodicClock, APhaseCorrectionMovesTowardsTheNearerAlignedTickBoundedPerTick) {
  using D = PeriodicClock::Clock::duration;
  const D period = milliseconds(1);
  EXPECT_EQ(phase_correction(D::zero(), period), D::zero());
  EXPECT_EQ(phase_correction(microseconds(80), period), -microseconds(10));
  EXPECT_EQ(phase_correction(microseconds(400), period), -microseconds(20));  // at most 2 %
  EXPECT_EQ(phase_correction(microseconds(920), period), microseconds(10));   // 80 us early
  EXPECT_EQ(phase_correction(-microseconds(80), period), microseconds(10));
  EXPECT_EQ(phase_correction(5 * period + microseconds(80), period), -microseconds(10));
  EXPECT_EQ(phase_correction(-7 * period - microseconds(80), period), microseconds(10));
  EXPECT_EQ(phase_correction(microseconds(80), D::zero()), D::zero());
}

// Ticks aligned to an event come to fall on it plus whole periods, each tick within 2 %
// of the period meanwhile. The deadlines do not depend on when the waits return (only
// a stall of more than max_burst periods drops ticks, whole periods), so this is exact.
TEST(PeriodicClock, AlignedTicksComeToFallOnTheEventPlusWholePeriods) {
  PeriodicClock clock(milliseconds(1), microseconds(200));
  clock.start();
  const PeriodicClock::Clock::time_point event = clock.deadline() + microseconds(430);
  clock.align(event);
  PeriodicClock::Clock::time_point before = clock.deadline();
  for (int i = 0; i < 80; ++i) {
    clock.wait();
    const PeriodicClock::Clock::duration gap = clock.tick() - before;
    before = clock.tick();
    if (i == 0) continue;  // the first tick's gap is from the unaligned deadline
    const auto periods = (gap + microseconds(500)) / milliseconds(1);
    const PeriodicClock::Clock::duration off = gap - periods * milliseconds(1);
    EXPECT_LE(std::chrono::abs(off), microseconds(20)) << "tick " << i;
  }
  const PeriodicClock::Clock::duration phase = (clock.deadline() - event) % milliseconds(1);
  EXPECT_TRUE(std::chrono::abs(phase) <= microseconds(1) ||
              std::chrono::abs(phase) >= milliseconds(1) - microseconds(1))
      << phase.count() << " ns";
}

}  // namespace
}  // namespace frusta
