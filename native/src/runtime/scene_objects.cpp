// SPDX-License-Identifier: MIT
#include "runtime/scene_objects.h"

#include <algorithm>

#include "runtime/object_dynamics.h"

namespace frusta {

SceneObjects::SceneObjects(int32_t capacity)
    : slots_(static_cast<size_t>(capacity)),
      active_index_(static_cast<size_t>(capacity), -1),
      broad_phase_(capacity),
      proxy_(static_cast<size_t>(capacity), BroadPhase::kNull),
      stale_in_(static_cast<size_t>(capacity), 0),
      reacted_in_(static_cast<size_t>(capacity), 0),
      placed_(static_cast<size_t>(capacity), 0) {
  const size_t n = static_cast<size_t>(capacity);
  active_.reserve(n);
  active_slot_.reserve(n);
  active_material_.reserve(n);
  for (std::vector<int32_t>& stale : stale_) stale.reserve(n);
  reacted_.reserve(n);
  placed_list_.reserve(n);
  dynamic_.reserve(n);
}

void SceneObjects::changed(int32_t slot) {
  uint8_t& in = stale_in_[static_cast<size_t>(slot)];
  for (int b = 0; b < 3; ++b)
    if (!(in & (1 << b))) {
      in = static_cast<uint8_t>(in | (1 << b));
      stale_[b].push_back(slot);  // within the capacity: each slot is listed once
    }
}

void SceneObjects::track(int32_t slot) {
  const Slot& s = slots_[static_cast<size_t>(slot)];
  int32_t& proxy = proxy_[static_cast<size_t>(slot)];
  const bool present = s.tree && !s.tree->tree.empty();  // an empty tree meets nothing
  if (!present) {
    if (proxy != BroadPhase::kNull) broad_phase_.destroy_proxy(proxy);
    proxy = BroadPhase::kNull;
    return;
  }
  const Aabb box = sphere_box(object_bound(SolverObject{&s.tree->tree, s.def.pose}));
  if (proxy == BroadPhase::kNull)
    proxy = broad_phase_.create_proxy(box, slot);  // one leaf per slot: within its capacity
  else
    broad_phase_.move_proxy(proxy, box);
}

int32_t SceneObjects::find(const Aabb& box, int32_t* out, int32_t capacity) const {
  int32_t count = 0;
  broad_phase_.query(box, [&](int32_t slot) {
    if (count < capacity) out[count] = active_index_[static_cast<size_t>(slot)];
    ++count;
  });
  return count;
}

bool SceneObjects::apply(const WorldCommand& c) {
  Slot& slot = slots_[static_cast<size_t>(c.slot)];
  const bool was_dynamic = slot.tree && slot.def.dynamic;
  auto place = [&] {
    if (placed_[static_cast<size_t>(c.slot)]) return;
    placed_[static_cast<size_t>(c.slot)] = 1;
    placed_list_.push_back(c.slot);
  };
  switch (c.kind) {
    case CommandKind::kAddObject:
      place();
      slot.tree = c.tree;
      slot.generation = c.generation;
      slot.def = c.def;
      slot.ignored_by = 0;
      break;
    case CommandKind::kRemoveObject:
      slot.tree = nullptr;
      slot.ignored_by = 0;
      break;
    case CommandKind::kObjectPose:
      place();
      slot.def.pose = c.def.pose;
      slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
      break;
    case CommandKind::kObjectDynamic:
      slot.def.dynamic = c.def.dynamic;
      slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
      break;
    case CommandKind::kAddHand:
    case CommandKind::kRemoveHand:
      return false;  // the world's
  }
  changed(c.slot);
  if (c.kind != CommandKind::kObjectDynamic) track(c.slot);
  const bool rebuild = c.kind == CommandKind::kAddObject || c.kind == CommandKind::kRemoveObject;
  // a host moving a held object each frame: its pose in the present list, not a rebuild
  // of the list (until a rebuild, the list and active_index_ still agree)
  const int32_t index = active_index_[static_cast<size_t>(c.slot)];
  if (c.kind == CommandKind::kObjectPose && index >= 0) {
    active_[static_cast<size_t>(index)].pose = slot.def.pose;
    moved_ = true;
  }
  // the dynamic list, kept in slot order so that objects move in the same order as
  // before it existed
  const bool is_dynamic = slot.tree && slot.def.dynamic;
  if (is_dynamic == was_dynamic) return rebuild;
  if (is_dynamic)
    dynamic_.insert(std::lower_bound(dynamic_.begin(), dynamic_.end(), c.slot), c.slot);
  else
    dynamic_.erase(std::lower_bound(dynamic_.begin(), dynamic_.end(), c.slot));
  return rebuild;
}

void SceneObjects::set_ignored(int32_t slot, int32_t hand, bool ignored) {
  const uint64_t bit = uint64_t{1} << hand;
  uint64_t& by = slots_[static_cast<size_t>(slot)].ignored_by;
  by = ignored ? by | bit : by & ~bit;
  changed(slot);
}

void SceneObjects::forget_hand(int32_t hand) {
  // every slot, but only when a hand leaves
  const uint64_t bit = uint64_t{1} << hand;
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].ignored_by & bit) {
      slots_[s].ignored_by &= ~bit;
      changed(static_cast<int32_t>(s));
    }
}

void SceneObjects::rebuild_active() {
  moved_ = true;
  active_.clear();  // within the capacity reserved up front: no allocation
  active_slot_.clear();
  active_material_.clear();
  for (size_t s = 0; s < slots_.size(); ++s) {
    active_index_[s] = slots_[s].tree ? static_cast<int32_t>(active_.size()) : -1;
    if (slots_[s].tree) {
      active_.push_back({&slots_[s].tree->tree, slots_[s].def.pose});
      active_slot_.push_back(static_cast<int32_t>(s));
      active_material_.push_back(slots_[s].def.material);
    }
  }
}

void SceneObjects::clear_reactions() {
  for (int32_t s : reacted_) {
    slots_[static_cast<size_t>(s)].reaction = ObjectWrench{};
    reacted_in_[static_cast<size_t>(s)] = 0;
    changed(s);  // published with a reaction, next with none
  }
  reacted_.clear();
}

void SceneObjects::add_reaction(int32_t slot, const ObjectWrench& wrench) {
  if (wrench.force == vec3(0.0) && wrench.torque == vec3(0.0)) return;  // nothing to add
  if (!reacted_in_[static_cast<size_t>(slot)]) {
    reacted_in_[static_cast<size_t>(slot)] = 1;
    reacted_.push_back(slot);
    changed(slot);
  }
  ObjectWrench& total = slots_[static_cast<size_t>(slot)].reaction;
  total.force += wrench.force;
  total.torque += wrench.torque;
}

void SceneObjects::publish(std::vector<ObjectSnapshot>& snapshot, int buffer) {
  std::vector<int32_t>& stale = stale_[buffer];
  for (int32_t s : stale) {
    stale_in_[static_cast<size_t>(s)] &= static_cast<uint8_t>(~(1 << buffer));
    const Slot& slot = slots_[static_cast<size_t>(s)];
    ObjectSnapshot& o = snapshot[static_cast<size_t>(s)];
    o.present = slot.tree != nullptr;
    o.dynamic = slot.def.dynamic;
    o.generation = slot.generation;
    o.pose = slot.def.pose;  // where the hands met it this step
    o.linear_velocity = slot.def.linear_velocity;
    o.angular_velocity = slot.def.angular_velocity;
    o.reaction = slot.reaction;
    o.ignored_by = slot.ignored_by;
  }
  stale.clear();
}

void SceneObjects::end_step(const vec3& gravity, double dt) {
  for (int32_t s : placed_list_) placed_[static_cast<size_t>(s)] = 0;
  placed_list_.clear();
  moved_ = false;
  // the dynamic objects move, and the present list's poses with them
  for (int32_t s : dynamic_) {
    Slot& slot = slots_[static_cast<size_t>(s)];
    advance_object(slot.def, slot.reaction, gravity, dt);
    active_[static_cast<size_t>(active_index_[static_cast<size_t>(s)])].pose = slot.def.pose;
    changed(s);
    track(s);  // re-inserted only once it leaves its fat box
    moved_ = true;
  }
}

}  // namespace frusta
