// SPDX-License-Identifier: MIT
#include "core/triple_buffer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>

namespace frusta {
namespace {

TEST(TripleBuffer, ReaderSeesTheNewestPublishedValue) {
  TripleBuffer<int> buffer(7);
  EXPECT_EQ(buffer.read(), 7) << "nothing published yet: the initial value";
  EXPECT_FALSE(buffer.fresh());
  buffer.write_slot() = 1;
  buffer.publish();
  buffer.write_slot() = 2;
  buffer.publish();
  EXPECT_TRUE(buffer.fresh());
  EXPECT_EQ(buffer.read(), 2) << "the newest, not the first";
  EXPECT_FALSE(buffer.fresh());
  EXPECT_EQ(buffer.read(), 2) << "nothing new: the same value again";
  buffer.write_slot() = 3;
  EXPECT_EQ(buffer.read(), 2) << "a slot being written is not published";
  buffer.publish();
  EXPECT_EQ(buffer.read(), 3);
}

// A snapshot whose every field derives from one counter: a torn read (fields from two
// different publishes) breaks the invariant.
struct Snapshot {
  uint64_t step = 0;
  double values[61] = {};
  uint64_t check = 0;
};

TEST(TripleBuffer, AReaderHammeringItNeverSeesATornOrOlderSnapshot) {
  TripleBuffer<Snapshot> buffer;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (uint64_t step = 1; !done.load(std::memory_order_relaxed); ++step) {
      Snapshot& s = buffer.write_slot();
      s.step = step;
      for (double& v : s.values) v = static_cast<double>(step);
      s.check = step * 2654435761u;
      buffer.publish();
    }
  });
  // at least 10^6 reads and 100 distinct snapshots: on a loaded machine the writer may
  // get little time, so the reads go on until it has progressed (bounded by a minute)
  constexpr uint64_t kReads = 1000000, kDistinct = 100;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  uint64_t reads = 0, last = 0, torn = 0, backwards = 0, distinct = 0;
  while ((reads < kReads || distinct < kDistinct) && std::chrono::steady_clock::now() < give_up) {
    for (int i = 0; i < 1000; ++i, ++reads) {
      const Snapshot& s = buffer.read();
      bool consistent = s.check == s.step * 2654435761u;
      for (double v : s.values) consistent &= v == static_cast<double>(s.step);
      torn += !consistent;
      backwards += s.step < last;
      distinct += s.step != last;
      last = s.step;
    }
  }
  done = true;
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_GE(reads, kReads);
  EXPECT_GE(distinct, kDistinct) << "the reader saw the writer progress";
}

}  // namespace
}  // namespace frusta
