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

namespace {

// slot generation <-> id generation: the mix undoes itself
uint16_t mixed_generation(frusta_world_id world, uint32_t generation) {
  return static_cast<uint16_t>(generation ^ (world.generation & 0xFF00u));
}

// The slot and slot generation of an id of a thing of `kind` in this world.
frusta_result slot_of(frusta_world_id world, int32_t index1, uint16_t world0, uint16_t generation,
                      const char* kind, int32_t* slot, uint32_t* slot_generation) {
  if (index1 == 0) return fail(FRUSTA_ERROR_NULL_ID, "%s id is null (zero-initialised)", kind);
  if (world0 != world_tag(world))
    return fail(FRUSTA_ERROR_STALE_ID,
                "%s id {index1=%d, world0=%u} belongs to another world, or to a destroyed one",
                kind, index1, world0);
  if (index1 < 0)  // never issued; and index1 - 1 would overflow for INT32_MIN
    return fail(FRUSTA_ERROR_STALE_ID, "%s id {index1=%d, generation=%u} names no %s of this world",
                kind, index1, generation, kind);
  *slot = index1 - 1;
  *slot_generation = mixed_generation(world, generation);
  return FRUSTA_OK;
}

}  // namespace

frusta_object_id object_id(frusta_world_id world, ObjectHandle object) {
  return {object.slot + 1, world_tag(world), mixed_generation(world, object.generation)};
}

frusta_hand_id hand_id(frusta_world_id world, HandHandle hand) {
  return {hand.slot + 1, world_tag(world), mixed_generation(world, hand.generation)};
}

frusta_result object_handle(frusta_world_id world, frusta_object_id id, ObjectHandle* out) {
  return slot_of(world, id.index1, id.world0, id.generation, "object", &out->slot, &out->generation);
}

frusta_result hand_handle(frusta_world_id world, frusta_hand_id id, HandHandle* out) {
  if (id.index1 != 0 && id.world0 == 0)
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d, world0=0, generation=%u} names a standalone hand "
                "(frusta_create_hand), not a hand of a world (frusta_create_world_hand)",
                id.index1, id.generation);
  return slot_of(world, id.index1, id.world0, id.generation, "hand", &out->slot, &out->generation);
}

bool world_hand_is_valid(frusta_hand_id id) {
  if (id.index1 < 1 || id.world0 == 0) return false;
  WorldObject* w = nullptr;
  frusta_world_id world;
  if (world_registry().find_by_tag(id.world0, nullptr, &w, &world) != FRUSTA_OK) return false;
  return w->world.hand_is_live({id.index1 - 1, mixed_generation(world, id.generation)});
}

bool WorldRegistry::is_valid(frusta_world_id id) const {
  WorldObject* world = nullptr;
  return find(id, false, &world) == FRUSTA_OK;
}

}  // namespace frusta
