// SPDX-License-Identifier: MIT
#include "core/id_pool.h"

#include <cassert>

namespace frusta {

IdPool::IdPool(int32_t capacity) : capacity_(capacity), slots_(new Slot[static_cast<size_t>(capacity)]) {
  free_.reserve(static_cast<size_t>(capacity));
}

bool IdPool::acquire(int32_t* slot, uint16_t* generation) {
  int32_t s;
  if (!free_.empty()) {
    s = free_.back();
    free_.pop_back();
  } else if (unused_ < capacity_) {
    s = unused_++;
  } else {
    return false;
  }
  Slot& taken = slots_[static_cast<size_t>(s)];
  taken.taken.store(true, std::memory_order_release);
  *slot = s;
  *generation = taken.generation.load(std::memory_order_relaxed);
  return true;
}

void IdPool::retire(int32_t slot) {
  Slot& s = slots_[static_cast<size_t>(slot)];
  assert(s.taken.load(std::memory_order_relaxed));
  // the generation first: a lookup racing this sees a stale id, not a slot being emptied
  const uint16_t g = s.generation.load(std::memory_order_relaxed);
  s.generation.store(static_cast<uint16_t>(g == UINT16_MAX ? 1 : g + 1), std::memory_order_release);
  s.taken.store(false, std::memory_order_release);
}

void IdPool::reclaim(int32_t slot) {
  assert(!slots_[static_cast<size_t>(slot)].taken.load(std::memory_order_relaxed));
  free_.push_back(slot);  // within the capacity reserved up front
}

bool IdPool::is_live(int32_t slot, uint16_t generation) const {
  if (slot < 0 || slot >= capacity_) return false;
  const Slot& s = slots_[static_cast<size_t>(slot)];
  return s.generation.load(std::memory_order_acquire) == generation &&
         s.taken.load(std::memory_order_acquire);
}

}  // namespace frusta
