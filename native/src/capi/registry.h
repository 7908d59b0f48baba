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
#include "core/id_pool.h"
#include "frusta/frusta.h"

namespace frusta {

// Id is one of the frusta_*_id structs: {int32 index1; uint16 world0; uint16 generation}.
template <class Object, class Id>
class Registry {
 public:
  explicit Registry(const char* kind) : kind_(kind), ids_(kMaxObjects) {}

  frusta_result add(std::unique_ptr<Object> object, Id* out) {
    std::lock_guard<std::mutex> lock(mutex_);
    int32_t slot = 0;
    uint16_t generation = 0;
    if (!ids_.acquire(&slot, &generation))
      return fail(FRUSTA_ERROR_CAPACITY, "too many %ss alive (%d)", kind_, kMaxObjects);
    if (objects_.size() <= static_cast<size_t>(slot)) objects_.resize(static_cast<size_t>(slot) + 1);
    objects_[static_cast<size_t>(slot)] = std::move(object);
    *out = Id{slot + 1, 0, generation};
    return FRUSTA_OK;
  }

  frusta_result destroy(Id id) {
    std::shared_ptr<Object> doomed;  // released after the lock is
    {
      std::lock_guard<std::mutex> lock(mutex_);
      Object* object = nullptr;
      if (frusta_result r = find_locked(id, true, &object)) return r;
      doomed = std::move(objects_[static_cast<size_t>(id.index1 - 1)]);
      ids_.release(id.index1 - 1);
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
    *out = objects_[static_cast<size_t>(id.index1 - 1)];
    return FRUSTA_OK;
  }

  bool is_valid(Id id) {
    std::lock_guard<std::mutex> lock(mutex_);
    Object* object = nullptr;
    return find_locked(id, false, &object) == FRUSTA_OK;
  }

 private:
  // slots are int32 indices + 1 in ids; far more than any scene needs
  static constexpr int32_t kMaxObjects = 1 << 16;

  frusta_result find_locked(Id id, bool report, Object** out) {
    if (id.index1 == 0) {
      return report ? fail(FRUSTA_ERROR_NULL_ID, "%s id is null (zero-initialised)", kind_)
                    : FRUSTA_ERROR_NULL_ID;
    }
    // index1 - 1 would overflow for INT32_MIN: is_live takes any slot number
    const int32_t slot = id.index1 > 0 ? id.index1 - 1 : -1;
    if (id.world0 != 0 || !ids_.is_live(slot, id.generation)) {
      return report ? fail(FRUSTA_ERROR_STALE_ID, "%s id {index1=%d, world0=%u, generation=%u} "
                           "names no live %s: it was destroyed or never created",
                           kind_, id.index1, id.world0, id.generation, kind_)
                    : FRUSTA_ERROR_STALE_ID;
    }
    *out = objects_[static_cast<size_t>(slot)].get();
    return FRUSTA_OK;
  }

  const char* kind_;
  std::mutex mutex_;  // create/destroy/find are host calls, never on a 1 kHz path
  IdPool ids_;
  std::vector<std::shared_ptr<Object>> objects_;  // by slot
};

}  // namespace frusta
