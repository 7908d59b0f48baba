// SPDX-License-Identifier: MIT
// One writer hands whole values to one reader without locks, waits or tearing: three
// slots, one the writer fills, one the reader holds, one in between, swapped by a single
// atomic exchange. The reader always gets the newest value published (or keeps its
// own if nothing new came); the writer never waits for a slow reader. How the 1 kHz
// thread publishes its output snapshot and how a host publishes haptic input.
#pragma once

#include <atomic>
#include <cstdint>

namespace frusta {

template <class T>
class TripleBuffer {
 public:
  TripleBuffer() = default;
  explicit TripleBuffer(const T& initial) : slots_{initial, initial, initial} {}
  TripleBuffer(const TripleBuffer&) = delete;
  TripleBuffer& operator=(const TripleBuffer&) = delete;

  // Only while neither side runs (set-up): every slot becomes value, and nothing is
  // waiting to be read.
  void reset(const T& value) {
    for (T& slot : slots_) slot = value;
    write_ = 0;
    read_ = 1;
    middle_.store(2u, std::memory_order_release);
  }

  // Writer thread only: the slot to fill, then publish() it, and which of the three it
  // is (0..2), for a writer that keeps data of its own per slot.
  T& write_slot() { return slots_[write_]; }
  int write_index() const { return static_cast<int>(write_); }
  void publish() {
    const uint32_t previous = middle_.exchange(write_ | kFresh, std::memory_order_acq_rel);
    write_ = previous & kIndex;
  }

  // Reader thread only: the newest published value; stays valid and unchanged until
  // the next call to read() from this thread.
  const T& read() {
    if (middle_.load(std::memory_order_relaxed) & kFresh) {
      const uint32_t previous = middle_.exchange(read_, std::memory_order_acq_rel);
      read_ = previous & kIndex;
    }
    return slots_[read_];
  }

  // Reader thread only: whether a value newer than the last read() is waiting.
  bool fresh() const { return (middle_.load(std::memory_order_acquire) & kFresh) != 0; }

 private:
  static constexpr uint32_t kIndex = 3u;
  static constexpr uint32_t kFresh = 4u;

  T slots_[3]{};
  uint32_t write_ = 0;                    // owned by the writer
  uint32_t read_ = 1;                     // owned by the reader
  std::atomic<uint32_t> middle_{2u};      // the slot in between, and whether it is new
};

}  // namespace frusta
