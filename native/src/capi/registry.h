// SPDX-License-Identifier: MIT
// A pool of standalone objects behind small ids: a destroyed object's id (and
// every copy of it) turns stale, never dangling, through the slot's generation.
// Objects are shared: whoever took a reference (a world using a tree) keeps the
// object alive past the destruction of its id.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "frusta/frusta.h"

namespace frusta {

// Id is one of the frusta_*_id structs: {int32 index1; uint16 world0; uint16 generation}.
template <class Object, class Id>
class Registry {
 public:
  explicit Registry(const char* kind) : kind_(kind) {}

  frusta_result add(std::unique_ptr<Object> object, Id* out) {
    std::lock_guard<std::mutex> lock(mutex_);
    int32_t index;
    if (!free_.empty()) {
      index = free_.back();
      free_.pop_back();
    } else {
      if (slots_.size() >= kMaxObjects)
        return fail(FRUSTA_ERROR_CAPACITY, "too many %ss alive (%zu)", kind_, kMaxObjects);
      index = static_cast<int32_t>(slots_.size());
      slots_.emplace_back();
    }
    Slot& slot = slots_[static_cast<size_t>(index)];
    slot.object = std::move(object);
    *out = Id{index + 1, 0, slot.generation};
    return FRUSTA_OK;
  }

  frusta_result destroy(Id id) {
    std::shared_ptr<Object> doomed;  // released after the lock is
    {
      std::lock_guard<std::mutex> lock(mutex_);
      Object* object = nullptr;
      if (frusta_result r = find_locked(id, true, &object)) return r;
      Slot& slot = slots_[static_cast<size_t>(id.index1 - 1)];
      doomed = std::move(slot.object);
      // skip 0 on wrap-around so a zero-initialised id never matches
      slot.generation = static_cast<uint16_t>(slot.generation == UINT16_MAX ? 1 : slot.generation + 1);
      free_.push_back(id.index1 - 1);
    }
    return FRUSTA_OK;
  }

  // The live object of id in *out, or an error (null or stale id) with the message set.
  frusta_result find(Id id, Object** out) {
    std::lock_guard<std::mutex> lock(mutex_);
    return find_locked(id, true, out);
  }

  // The live object of id, shared: it outlives the destruction of its id.
  frusta_result find_shared(Id id, std::shared_ptr<Object>* out) {
    std::lock_guard<std::mutex> lock(mutex_);
    Object* object = nullptr;
    if (frusta_result r = find_locked(id, true, &object)) return r;
    *out = slots_[static_cast<size_t>(id.index1 - 1)].object;
    return FRUSTA_OK;
  }

  bool is_valid(Id id) {
    std::lock_guard<std::mutex> lock(mutex_);
    Object* object = nullptr;
    return find_locked(id, false, &object) == FRUSTA_OK;
  }

 private:
  // slots are int32 indices + 1 in ids; far more than any scene needs
  static constexpr size_t kMaxObjects = 1 << 16;

  struct Slot {
    uint16_t generation = 1;  // ids with generation 0 are never issued
    std::shared_ptr<Object> object;
  };

  frusta_result find_locked(Id id, bool report, Object** out) {
    if (id.index1 == 0) {
      return report ? fail(FRUSTA_ERROR_NULL_ID, "%s id is null (zero-initialised)", kind_)
                    : FRUSTA_ERROR_NULL_ID;
    }
    const size_t index = static_cast<size_t>(id.index1) - 1;
    if (id.index1 < 0 || index >= slots_.size() || id.world0 != 0 ||
        slots_[index].generation != id.generation || !slots_[index].object) {
      return report ? fail(FRUSTA_ERROR_STALE_ID, "%s id {index1=%d, world0=%u, generation=%u} "
                           "names no live %s: it was destroyed or never created",
                           kind_, id.index1, id.world0, id.generation, kind_)
                    : FRUSTA_ERROR_STALE_ID;
    }
    *out = slots_[index].object.get();
    return FRUSTA_OK;
  }

  const char* kind_;
  std::mutex mutex_;  // create/destroy/find are host calls, never on a 1 kHz path
  std::vector<Slot> slots_;
  std::vector<int32_t> free_;
};

}  // namespace frusta
