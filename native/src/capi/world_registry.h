// SPDX-License-Identifier: MIT
// Worlds behind frusta_world_id. Unlike the other registries, finding a world takes no
// lock: frusta_world_set_haptic is called from device threads at the glove's rate, and
// must never wait for a host thread creating or destroying another world.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/id_pool.h"
#include "devices/device_link.h"
#include "frusta/frusta.h"
#include "runtime/world.h"

namespace frusta {

struct WorldObject {
  explicit WorldObject(const WorldDef& def)
      : world(def),
        gloves(static_cast<size_t>(def.max_hands)),
        glove_generation(static_cast<size_t>(def.max_hands), 0) {}
  World world;
  const WorldSnapshot* latched = nullptr;  // by frusta_world_read; host thread only
  // one per hand slot; declared after the world, so they close (and zero their gloves)
  // before it goes
  std::vector<std::unique_ptr<DeviceLink>> gloves;  // host thread only
  std::vector<uint16_t> glove_generation;           // host thread only
};

// An object's, a hand's or a glove's world0: the world's slot + 1 in the low byte and
// its generation's low byte above.
uint16_t world_tag(frusta_world_id world);

// Objects and hands of a world as the header names them: slot + 1, the world's tag, and
// the slot's generation with the world generation's high byte mixed in (world0 holds
// only its low byte: without the mix, an id of a world destroyed 256 generations of
// its slot ago named the slot's new world's object or hand).
frusta_object_id object_id(frusta_world_id world, ObjectHandle object);
frusta_hand_id hand_id(frusta_world_id world, HandHandle hand);
// The handle an id names in this world, or why not (the thread's error names the id):
// null, another world's (a hand: or a standalone one), or never issued. Whether the
// thing is there now is the caller's to check, against the host's view or a snapshot.
frusta_result object_handle(frusta_world_id world, frusta_object_id id, ObjectHandle* out);
frusta_result hand_handle(frusta_world_id world, frusta_hand_id id, HandHandle* out);
// 1 if id names a live hand of a live world (never an error). Lock-free.
bool world_hand_is_valid(frusta_hand_id id);

class WorldRegistry {
 public:
  static constexpr int32_t kMaxWorlds = 255;  // a slot + 1 fits an object id's byte

  frusta_result create(const WorldDef& def, frusta_world_id* out);
  // No other thread may use the world meanwhile (documented in the header).
  frusta_result destroy(frusta_world_id id);
  // Lock-free: the world of id in *out, or an error (null or stale id).
  frusta_result find(frusta_world_id id, WorldObject** out) const;
  bool is_valid(frusta_world_id id) const;
  // Lock-free: the world a world_tag() names, with its full id, or a stale-id error
  // naming `what` (e.g. "device"; null: no message is set).
  frusta_result find_by_tag(uint16_t tag, const char* what, WorldObject** out,
                            frusta_world_id* id) const;

 private:
  frusta_result find(frusta_world_id id, bool report, WorldObject** out) const;

  std::mutex create_mutex_;  // serialises create/destroy (host calls) only
  IdPool ids_{kMaxWorlds};
  std::array<std::atomic<WorldObject*>, kMaxWorlds> worlds_{};
};

WorldRegistry& world_registry();

}  // namespace frusta
