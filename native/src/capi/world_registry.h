// SPDX-License-Identifier: MIT
// Worlds behind frusta_world_id. Unlike the other registries, finding a world takes no
// lock: frusta_world_set_haptic is called from device threads at the glove's rate, and
// must never wait for a host thread creating or destroying another world.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>

#include "core/id_pool.h"
#include "devices/device_link.h"
#include "frusta/frusta.h"
#include "runtime/world.h"

namespace frusta {

// Gloves drive the first kMaxGloves hands of a world, one each.
constexpr int32_t kMaxGloves = 16;

struct WorldObject {
  explicit WorldObject(const WorldDef& def) : world(def) {}
  World world;
  const WorldSnapshot* latched = nullptr;  // by frusta_world_read; host thread only
  // declared after the world, so they close (and zero their gloves) before it goes
  std::array<std::unique_ptr<DeviceLink>, kMaxGloves> gloves;  // host thread only
  std::array<uint16_t, kMaxGloves> glove_generation{};        // host thread only
};

// An object's or a glove's world0: the world's slot + 1 in the low byte and its
// generation's low byte above.
uint16_t world_tag(frusta_world_id world);

// A world's hand as the header names it: its index + 1, the world's tag, and the
// world's whole generation (hands are never removed, so the world's generation tells a
// hand of this world from one of a world that had the slot 256 generations ago).
frusta_hand_id world_hand_id(frusta_world_id world, int32_t hand);
// The index of a hand id in this world, or why not: null, standalone (world0 0),
// another world's, or never issued (STALE_ID naming it).
frusta_result world_hand_index(frusta_world_id world, const WorldObject& w, frusta_hand_id id,
                               int32_t* out);
// 1 if id names a hand of a live world (never an error).
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
