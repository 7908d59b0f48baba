// SPDX-License-Identifier: MIT
#include "capi/world_registry.h"

#include <memory>

#include "core/error.h"

namespace frusta {

WorldRegistry& world_registry() {
  static WorldRegistry registry;
  return registry;
}

frusta_result WorldRegistry::create(const WorldDef& def, frusta_world_id* out) {
  std::lock_guard<std::mutex> lock(create_mutex_);
  auto world = std::make_unique<WorldObject>(def);
  int32_t slot = 0;
  uint16_t generation = 0;
  if (!ids_.acquire(&slot, &generation))
    return fail(FRUSTA_ERROR_CAPACITY, "too many worlds alive (%d)", kMaxWorlds);
  worlds_[static_cast<size_t>(slot)].store(world.release(), std::memory_order_release);
  *out = frusta_world_id{slot + 1, 0, generation};
  return FRUSTA_OK;
}

frusta_result WorldRegistry::destroy(frusta_world_id id) {
  std::unique_ptr<WorldObject> doomed;
  {
    std::lock_guard<std::mutex> lock(create_mutex_);
    WorldObject* world = nullptr;
    if (frusta_result r = find(id, true, &world)) return r;
    // the id first: a lookup racing this sees a stale id, not a dying world
    ids_.release(id.index1 - 1);
    worlds_[static_cast<size_t>(id.index1 - 1)].store(nullptr, std::memory_order_release);
    doomed.reset(world);
  }
  return FRUSTA_OK;  // the world's thread is stopped and joined as it is freed, unlocked
}

frusta_result WorldRegistry::find(frusta_world_id id, bool report, WorldObject** out) const {
  if (id.index1 == 0)
    return report ? fail(FRUSTA_ERROR_NULL_ID, "world id is null (zero-initialised)")
                  : FRUSTA_ERROR_NULL_ID;
  WorldObject* world = nullptr;
  const int32_t slot = id.index1 > 0 ? id.index1 - 1 : -1;
  if (id.world0 == 0 && ids_.is_live(slot, id.generation))
    world = worlds_[static_cast<size_t>(slot)].load(std::memory_order_acquire);
  if (!world)
    return report ? fail(FRUSTA_ERROR_STALE_ID,
                         "world id {index1=%d, world0=%u, generation=%u} names no live world: it "
                         "was destroyed or never created",
                         id.index1, id.world0, id.generation)
                  : FRUSTA_ERROR_STALE_ID;
  *out = world;
  return FRUSTA_OK;
}

frusta_result WorldRegistry::find(frusta_world_id id, WorldObject** out) const {
  return find(id, true, out);
}

uint16_t world_tag(frusta_world_id world) {
  return static_cast<uint16_t>((world.index1 & 0xff) | ((world.generation & 0xff) << 8));
}

frusta_result WorldRegistry::find_by_tag(uint16_t tag, const char* what, WorldObject** out,
                                         frusta_world_id* id) const {
  const int32_t index1 = tag & 0xff;
  if (index1 >= 1 && index1 <= kMaxWorlds) {
    const uint16_t generation = ids_.generation(index1 - 1);
    WorldObject* world = worlds_[static_cast<size_t>(index1 - 1)].load(std::memory_order_acquire);
    if (world && (generation & 0xff) == (tag >> 8)) {
      *out = world;
      *id = frusta_world_id{index1, 0, generation};
      return FRUSTA_OK;
    }
  }
  if (what == nullptr) return FRUSTA_ERROR_STALE_ID;
  return fail(FRUSTA_ERROR_STALE_ID, "%s id's world (world0=%u) is destroyed or never existed",
              what, tag);
}

frusta_hand_id world_hand_id(frusta_world_id world, int32_t hand) {
  return {hand + 1, world_tag(world), world.generation};
}

frusta_result world_hand_index(frusta_world_id world, const WorldObject& w, frusta_hand_id id,
                               int32_t* out) {
  if (id.index1 == 0) return fail(FRUSTA_ERROR_NULL_ID, "hand id is null (zero-initialised)");
  if (id.world0 == 0)
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d, world0=0, generation=%u} names a standalone hand "
                "(frusta_create_hand), not a hand of a world (frusta_create_world_hand)",
                id.index1, id.generation);
  if (id.world0 != world_tag(world) || id.generation != world.generation)
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d, world0=%u, generation=%u} belongs to another world, or to "
                "a destroyed one",
                id.index1, id.world0, id.generation);
  // index1 is checked before 1 is taken off it: INT32_MIN - 1 overflows
  if (id.index1 < 1 || id.index1 > w.world.hand_count())
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d} names no hand of this world (it has %d)", id.index1,
                w.world.hand_count());
  *out = id.index1 - 1;
  return FRUSTA_OK;
}

bool world_hand_is_valid(frusta_hand_id id) {
  if (id.index1 == 0 || id.world0 == 0) return false;
  WorldObject* w = nullptr;
  frusta_world_id world;
  if (world_registry().find_by_tag(id.world0, nullptr, &w, &world) != FRUSTA_OK) return false;
  return id.generation == world.generation && id.index1 >= 1 && id.index1 <= w->world.hand_count();
}

bool WorldRegistry::is_valid(frusta_world_id id) const {
  WorldObject* world = nullptr;
  return find(id, false, &world) == FRUSTA_OK;
}

}  // namespace frusta
