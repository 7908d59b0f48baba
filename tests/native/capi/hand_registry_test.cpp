// SPDX-License-Identifier: MIT
// The slot pool behind frusta_hand_id (native/src/capi/hand_registry.cpp): ids are
// unique per slot generation, and every id of a destroyed hand stays stale.
#include "capi/hand_registry.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <set>
#include <thread>
#include <tuple>
#include <vector>

#include "capi_fixture.h"
#include "frusta/frusta.h"
#include "hand/anthropometry.h"

namespace frusta {
namespace {

// suite names start with "capi" so that `ctest -R capi` selects them
using capiHandRegistry = testing::CapiTest;

using Key = std::tuple<int32_t, uint16_t, uint16_t>;
Key key(frusta_hand_id id) { return {id.index1, id.world0, id.generation}; }

TEST_F(capiHandRegistry, ThousandCreateDestroyCyclesNeverReuseAnId) {
  HandRegistry registry;
  const HandDef def = default_hand_def();
  std::set<Key> issued;
  std::vector<frusta_hand_id> destroyed;
  for (int cycle = 0; cycle < 1000; ++cycle) {
    frusta_hand_id id{};
    ASSERT_EQ(registry.create(def, &id), FRUSTA_OK);
    EXPECT_FALSE(FRUSTA_IS_NULL(id));
    EXPECT_EQ(id.world0, 0);
    EXPECT_NE(id.generation, 0);
    EXPECT_EQ(id.index1, 1) << "a lone hand always reuses the first slot";
    EXPECT_TRUE(issued.insert(key(id)).second) << "id issued twice at cycle " << cycle;
    EXPECT_TRUE(registry.is_valid(id));
    ASSERT_EQ(registry.destroy(id), FRUSTA_OK);
    EXPECT_FALSE(registry.is_valid(id));
    destroyed.push_back(id);
  }
  // the slot is reused with a fresh generation every time, and no old id revives
  frusta_hand_id live{};
  ASSERT_EQ(registry.create(def, &live), FRUSTA_OK);
  EXPECT_TRUE(registry.is_valid(live));
  for (const frusta_hand_id& id : destroyed) {
    EXPECT_FALSE(registry.is_valid(id)) << "generation " << id.generation;
    HandObject* hand = nullptr;
    ExpectError(registry.find(id, &hand), FRUSTA_ERROR_STALE_ID, "destroyed");
    EXPECT_EQ(hand, nullptr);
  }
}

TEST_F(capiHandRegistry, InterleavedHandsKeepUniqueIdsAndOnlyLiveOnesAreValid) {
  HandRegistry registry;
  const HandDef def = default_hand_def();
  std::mt19937_64 rng(31);
  std::set<Key> issued;
  std::vector<frusta_hand_id> live, dead;
  for (int step = 0; step < 1000; ++step) {
    if (live.empty() || rng() % 3 != 0) {
      frusta_hand_id id{};
      ASSERT_EQ(registry.create(def, &id), FRUSTA_OK);
      EXPECT_TRUE(issued.insert(key(id)).second) << "id issued twice at step " << step;
      live.push_back(id);
    } else {
      const size_t pick = rng() % live.size();
      ASSERT_EQ(registry.destroy(live[pick]), FRUSTA_OK);
      dead.push_back(live[pick]);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(pick));
    }
  }
  std::set<HandObject*> objects;
  for (const frusta_hand_id& id : live) {
    EXPECT_TRUE(registry.is_valid(id));
    HandObject* hand = nullptr;
    ASSERT_EQ(registry.find(id, &hand), FRUSTA_OK);
    EXPECT_TRUE(objects.insert(hand).second) << "two live ids share an object";
  }
  for (const frusta_hand_id& id : dead) EXPECT_FALSE(registry.is_valid(id));
}

TEST_F(capiHandRegistry, NullAndStaleIdsAreInvalidWithoutAMessage) {
  HandRegistry registry;
  const HandDef def = default_hand_def();
  frusta_hand_id id{};
  ASSERT_EQ(registry.create(def, &id), FRUSTA_OK);

  EXPECT_FALSE(registry.is_valid(frusta_hand_id{}));
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{0, 0, id.generation}));
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{id.index1, 1, id.generation}));  // another world
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{id.index1, 0, 0}));
  EXPECT_FALSE(
      registry.is_valid(frusta_hand_id{id.index1, 0, static_cast<uint16_t>(id.generation + 1)}));
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{id.index1 + 1, 0, id.generation}));  // no such slot
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{-1, 0, id.generation}));
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{INT32_MIN, 0, id.generation}));
  EXPECT_FALSE(registry.is_valid(frusta_hand_id{INT32_MAX, 0, id.generation}));
  EXPECT_TRUE(registry.is_valid(id));
  EXPECT_STREQ(frusta_last_error(), "") << "is_valid is a question, not an error";

  HandObject* hand = nullptr;
  ExpectError(registry.find(frusta_hand_id{}, &hand), FRUSTA_ERROR_NULL_ID, "null");
  ExpectError(registry.destroy(frusta_hand_id{}), FRUSTA_ERROR_NULL_ID, "null");
  ExpectError(registry.find(frusta_hand_id{-1, 0, 1}, &hand), FRUSTA_ERROR_STALE_ID, "index1=-1");
  EXPECT_EQ(hand, nullptr);
  ASSERT_EQ(registry.destroy(id), FRUSTA_OK);
  ExpectError(registry.destroy(id), FRUSTA_ERROR_STALE_ID, "destroyed");
}

TEST_F(capiHandRegistry, FindReturnsTheHandBuiltFromItsDef) {
  HandRegistry registry;
  HandDef right = default_hand_def(), left = default_hand_def();
  left.side = FRUSTA_HAND_LEFT;
  left.joint_min[2][1] = 0.1;  // zero is clamped into the limits at creation
  frusta_hand_id a{}, b{};
  ASSERT_EQ(registry.create(right, &a), FRUSTA_OK);
  ASSERT_EQ(registry.create(left, &b), FRUSTA_OK);
  EXPECT_NE(a.index1, b.index1);
  HandObject *ha = nullptr, *hb = nullptr;
  ASSERT_EQ(registry.find(a, &ha), FRUSTA_OK);
  ASSERT_EQ(registry.find(b, &hb), FRUSTA_OK);
  EXPECT_FALSE(ha->model.left);
  EXPECT_TRUE(hb->model.left);
  EXPECT_EQ(hb->state.angles[2 * FRUSTA_JOINTS_PER_FINGER + 1], 0.1);
  // the pose is the forward kinematics of the state from the start
  EXPECT_EQ(hb->pose.fingers[2].joint[0].y, -left.base_position[2][1]);
}

// Generations are 16 bits: after 65535 reuses of a slot the counter wraps, skipping 0
// so that a zero-initialised generation never matches.
TEST_F(capiHandRegistry, GenerationWrapsAroundSkippingZero) {
  HandRegistry registry;
  const HandDef def = default_hand_def();
  frusta_hand_id first{}, id{};
  ASSERT_EQ(registry.create(def, &first), FRUSTA_OK);
  ASSERT_EQ(registry.destroy(first), FRUSTA_OK);
  uint16_t previous = first.generation;
  for (int cycle = 1; cycle <= 65535; ++cycle) {
    ASSERT_EQ(registry.create(def, &id), FRUSTA_OK);
    ASSERT_NE(id.generation, 0) << "cycle " << cycle;
    ASSERT_EQ(id.generation, previous == UINT16_MAX ? 1 : previous + 1) << "cycle " << cycle;
    previous = id.generation;
    ASSERT_EQ(registry.destroy(id), FRUSTA_OK);
  }
  EXPECT_EQ(previous, first.generation) << "65535 generations per slot, then they repeat";
}

// Thread contract: is_valid may be called from any thread while the main thread
// creates and destroys (run under TSan in CI to catch a data race).
TEST_F(capiHandRegistry, IsValidFromOtherThreadsWhileTheMainThreadCreatesAndDestroys) {
  HandRegistry registry;
  const HandDef def = default_hand_def();
  frusta_hand_id keep{};
  ASSERT_EQ(registry.create(def, &keep), FRUSTA_OK);
  std::atomic<bool> stop{false};
  std::atomic<int> wrong{0};
  std::vector<std::thread> readers;
  for (int t = 0; t < 3; ++t)
    readers.emplace_back([&] {
      while (!stop.load()) {
        if (!registry.is_valid(keep)) ++wrong;
        if (registry.is_valid(frusta_hand_id{})) ++wrong;
        registry.is_valid(frusta_hand_id{2, 0, 1});  // comes and goes
      }
    });
  for (int cycle = 0; cycle < 2000; ++cycle) {
    frusta_hand_id id{};
    ASSERT_EQ(registry.create(def, &id), FRUSTA_OK);
    ASSERT_EQ(registry.destroy(id), FRUSTA_OK);
  }
  stop = true;
  for (std::thread& t : readers) t.join();
  EXPECT_EQ(wrong.load(), 0);
}

// The registry behind the C ABI behaves the same way.
TEST_F(capiHandRegistry, AbiIdsOfDestroyedHandsStayStaleAfterTheirSlotIsReused) {
  const frusta_hand_def def = frusta_default_hand_def();
  std::set<Key> issued;
  std::vector<frusta_hand_id> dead;
  for (int cycle = 0; cycle < 1000; ++cycle) {
    frusta_hand_id id{};
    ASSERT_EQ(frusta_create_hand(&def, &id), FRUSTA_OK);
    EXPECT_TRUE(issued.insert(key(id)).second);
    EXPECT_EQ(frusta_hand_is_valid(id), 1);
    ASSERT_EQ(frusta_destroy_hand(id), FRUSTA_OK);
    EXPECT_EQ(frusta_hand_is_valid(id), 0);
    dead.push_back(id);
  }
  for (const frusta_hand_id& id : dead) EXPECT_EQ(frusta_hand_is_valid(id), 0);
  EXPECT_EQ(frusta_hand_is_valid(frusta_hand_id{}), 0);
}

}  // namespace
}  // namespace frusta
