// SPDX-License-Identifier: MIT
// A bounded single-producer single-consumer ring: the host queues commands (add or
// remove an object, change a pose) and the 1 kHz thread applies them at a step
// boundary. Lock-free, wait-free, no allocation after construction; a full queue
// refuses the push rather than block or grow, and says so.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace frusta {

template <class T>
class SpscQueue {
 public:
  // capacity: rounded up to a power of two
  explicit SpscQueue(size_t capacity) : slots_(round_up(capacity)), mask_(slots_.size() - 1) {}
  SpscQueue(const SpscQueue&) = delete;
  SpscQueue& operator=(const SpscQueue&) = delete;

  size_t capacity() const { return slots_.size(); }

  // Producer thread only. False when full (nothing is written).
  bool push(const T& value) {
    const size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) == slots_.size()) return false;
    slots_[head & mask_] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer thread only. False when empty.
  bool pop(T& out) {
    const size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

 private:
  static size_t round_up(size_t n) {
    size_t p = 1;
    while (p < n) p <<= 1;
    return p;
  }

  std::vector<T> slots_;
  size_t mask_;
  // on separate cache lines so producer and consumer do not share one
  alignas(64) std::atomic<size_t> head_{0};  // next slot to write
  alignas(64) std::atomic<size_t> tail_{0};  // next slot to read
};

}  // namespace frusta
