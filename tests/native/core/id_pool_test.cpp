// SPDX-License-Identifier: MIT
// The one id pool: slots reused last-freed first, a freed slot's ids stale for good
// (through 65535 reuses and the wrap past it), generation 0 never live.
#include "core/id_pool.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace frusta {
namespace {

TEST(IdPool, SlotsComeLowestFirstThenLastFreedFirst) {
  IdPool pool(3);
  int32_t a, b, c, d;
  uint16_t ga, gb, gc, gd;
  ASSERT_TRUE(pool.acquire(&a, &ga));
  ASSERT_TRUE(pool.acquire(&b, &gb));
  ASSERT_TRUE(pool.acquire(&c, &gc));
  EXPECT_EQ((std::set<int32_t>{a, b, c}), (std::set<int32_t>{0, 1, 2}));
  EXPECT_EQ(a, 0);
  EXPECT_FALSE(pool.acquire(&d, &gd)) << "full";
  pool.release(b);
  pool.release(a);
  ASSERT_TRUE(pool.acquire(&d, &gd));
  EXPECT_EQ(d, a) << "the slot freed last";
  EXPECT_NE(gd, ga) << "with a new generation";
}

TEST(IdPool, AnIdOfAFreedSlotStaysStaleThroughEveryReuse) {
  IdPool pool(1);
  std::set<uint16_t> seen;
  int32_t first = -1;
  uint16_t first_generation = 0;
  ASSERT_TRUE(pool.acquire(&first, &first_generation));
  EXPECT_TRUE(pool.is_live(first, first_generation));
  pool.release(first);
  for (int reuse = 0; reuse < 70000; ++reuse) {
    int32_t slot = -1;
    uint16_t generation = 0;
    ASSERT_TRUE(pool.acquire(&slot, &generation));
    ASSERT_EQ(slot, first);
    ASSERT_NE(generation, 0) << "0 is never live: a zero-initialised id names nothing";
    if (reuse < 65534) {  // before the 16-bit generation wraps round to the first one
      ASSERT_FALSE(pool.is_live(first, first_generation)) << "reuse " << reuse;
      ASSERT_TRUE(seen.insert(generation).second) << "a generation came back early";
    }
    ASSERT_TRUE(pool.is_live(slot, generation));
    pool.release(slot);
    ASSERT_FALSE(pool.is_live(slot, generation));
  }
}

// A slot whose old occupant is still being let go of: its ids are stale at once, and
// the slot is handed out again only once reclaimed.
TEST(IdPool, ARetiredSlotIsStaleAtOnceAndTakenAgainOnlyOnceReclaimed) {
  IdPool pool(2);
  int32_t a, b, c;
  uint16_t ga, gb, gc;
  ASSERT_TRUE(pool.acquire(&a, &ga));
  ASSERT_TRUE(pool.acquire(&b, &gb));
  pool.retire(a);
  EXPECT_FALSE(pool.is_live(a, ga));
  EXPECT_FALSE(pool.is_live(a, pool.generation(a))) << "not taken";
  EXPECT_FALSE(pool.acquire(&c, &gc)) << "the retired slot is not free yet";
  pool.reclaim(a);
  ASSERT_TRUE(pool.acquire(&c, &gc));
  EXPECT_EQ(c, a);
  EXPECT_NE(gc, ga);
  EXPECT_TRUE(pool.is_live(c, gc));
  EXPECT_FALSE(pool.is_live(a, ga));
}

TEST(IdPool, NothingOutsideTheSlotsIsLive) {
  IdPool pool(2);
  int32_t slot;
  uint16_t generation;
  ASSERT_TRUE(pool.acquire(&slot, &generation));
  EXPECT_FALSE(pool.is_live(-1, generation));
  EXPECT_FALSE(pool.is_live(2, generation));
  EXPECT_FALSE(pool.is_live(INT32_MIN, generation));
  EXPECT_FALSE(pool.is_live(1, pool.generation(1))) << "never taken";
  EXPECT_FALSE(pool.is_live(slot, 0));
}

}  // namespace
}  // namespace frusta
