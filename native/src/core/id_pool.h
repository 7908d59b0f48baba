// SPDX-License-Identifier: MIT
// The one way things get ids: slots 0..capacity-1, each with a 16-bit generation that
// is bumped when the slot is freed, so every copy of an id of what was there turns
// stale rather than naming whatever comes next. Generation 0 is never live, so a
// zero-initialised id names nothing. Worlds, their objects, hands and trees all take
// their ids from one of these.
//
// Threads: acquire and release from one thread at a time (the owner's, or under its
// lock); is_live and generation from any thread, lock-free.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace frusta {

class IdPool {
 public:
  explicit IdPool(int32_t capacity);
  IdPool(const IdPool&) = delete;
  IdPool& operator=(const IdPool&) = delete;

  // A free slot (the one freed last, else the lowest never used) and its generation;
  // false when every slot is taken.
  bool acquire(int32_t* slot, uint16_t* generation);
  // Free a taken slot: ids of what was there turn stale.
  void release(int32_t slot) {
    retire(slot);
    reclaim(slot);
  }
  // The same in two parts, for a slot whose old occupant is let go of later: ids of what
  // was there turn stale now (retire), and the slot is handed out again only after
  // reclaim.
  void retire(int32_t slot);
  void reclaim(int32_t slot);
  // Whether (slot, generation) names what is in a taken slot now.
  bool is_live(int32_t slot, uint16_t generation) const;
  uint16_t generation(int32_t slot) const {
    return slots_[static_cast<size_t>(slot)].generation.load(std::memory_order_acquire);
  }
  int32_t capacity() const { return capacity_; }

 private:
  struct Slot {
    std::atomic<uint16_t> generation{1};
    std::atomic<bool> taken{false};
  };
  int32_t capacity_;
  std::unique_ptr<Slot[]> slots_;
  std::vector<int32_t> free_;  // reclaimed slots, the last reclaimed last
  int32_t unused_ = 0;         // slots from here on were never taken
};

}  // namespace frusta
