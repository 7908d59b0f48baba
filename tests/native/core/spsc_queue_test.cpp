// SPDX-License-Identifier: MIT
#include "core/spsc_queue.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

namespace frusta {
namespace {

TEST(SpscQueue, FifoAndAFullQueueRefusesWithoutLosingAnything) {
  SpscQueue<int> queue(3);
  EXPECT_EQ(queue.capacity(), 4u) << "rounded up to a power of two";
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(queue.push(i));
  EXPECT_FALSE(queue.push(99)) << "full";
  int out = -1;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(queue.pop(out));
    EXPECT_EQ(out, i);
  }
  EXPECT_FALSE(queue.pop(out)) << "empty";
  EXPECT_EQ(out, 3) << "a failed pop writes nothing";
}

TEST(SpscQueue, TwoThreadsPassAMillionItemsInOrder) {
  SpscQueue<uint64_t> queue(256);
  constexpr uint64_t kItems = 1000000;
  std::thread producer([&] {
    for (uint64_t i = 0; i < kItems; ++i)
      while (!queue.push(i)) std::this_thread::yield();
  });
  uint64_t expected = 0, out = 0, misordered = 0;
  while (expected < kItems) {
    if (!queue.pop(out)) {
      std::this_thread::yield();
      continue;
    }
    misordered += out != expected;
    ++expected;
  }
  producer.join();
  EXPECT_EQ(misordered, 0u);
  EXPECT_FALSE(queue.pop(out));
}

}  // namespace
}  // namespace frusta
