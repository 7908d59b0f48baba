// SPDX-License-Identifier: MIT
#include "runtime/scene_objects.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "runtime/object_contact.h"
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
  // a host that adds, moves, removes or frees an object takes it out of any hold, and
  // wakes it; one that moves or removes an object may take away what others rest on
  slot.held_by = -1;
  slot.pushes_share = 1.0;
  wake(slot);
  if (c.kind == CommandKind::kObjectPose || c.kind == CommandKind::kRemoveObject)
    for (int32_t d : dynamic_) wake(slots_[static_cast<size_t>(d)]);
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
  for (size_t s = 0; s < slots_.size(); ++s) {
    if (slots_[s].ignored_by & bit) {
      slots_[s].ignored_by &= ~bit;
      changed(static_cast<int32_t>(s));
    }
    if (slots_[s].held_by == hand) {  // let go, as by an opened hand
      slots_[s].held_by = -1;
      slots_[s].pushes_share = 0.0;
    }
    if (slots_[s].offer_hand == hand) slots_[s].offer_hand = -1;
  }
}

void SceneObjects::offer_grasp(int32_t slot, int32_t hand, double load, const RigidPose& palm) {
  Slot& s = slots_[static_cast<size_t>(slot)];
  wake(s);
  if (hand == s.held_by) {
    s.holder_load = load;
    s.holder_palm = palm;
  } else if (load > s.offer_load) {
    s.offer_hand = hand;
    s.offer_load = load;
    s.offer_palm = palm;
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
  wake(slots_[static_cast<size_t>(slot)]);  // a hand pushes it
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
    o.reaction = slot.held_by >= 0 ? slot.carried : slot.reaction;
    o.ignored_by = slot.ignored_by;
    o.held_by = slot.held_by;
  }
  stale.clear();
}

void SceneObjects::end_step(const vec3& gravity, double dt) {
  for (int32_t s : placed_list_) placed_[static_cast<size_t>(s)] = 0;
  placed_list_.clear();
  moved_ = false;
  // what the objects do to each other, from where they all are, then every one moves
  for (int32_t s : dynamic_) touch_objects(s, dt);
  contact_cache_.end_step();
  // the dynamic objects move, and the present list's poses with them
  for (int32_t s : dynamic_) {
    Slot& slot = slots_[static_cast<size_t>(s)];
    const bool slept = slot.asleep;
    move_dynamic(slot, gravity, dt);
    if (slept && slot.asleep) continue;  // at rest: nothing moved, nothing to publish
    active_[static_cast<size_t>(active_index_[static_cast<size_t>(s)])].pose = slot.def.pose;
    changed(s);
    track(s);  // re-inserted only once it leaves its fat box
    moved_ = true;
  }
}

void SceneObjects::touch_objects(int32_t s, double dt) {
  Slot& slot = slots_[static_cast<size_t>(s)];
  if (slot.asleep || slot.tree->tree.empty()) return;  // a sleeping one waits to be woken
  const bool held = slot.held_by >= 0;
  const Aabb box = sphere_box(object_bound(SolverObject{&slot.tree->tree, slot.def.pose}));
  broad_phase_.query(box, [&](int32_t o) {
    Slot& other = slots_[static_cast<size_t>(o)];
    const bool yields = other.def.dynamic && other.held_by < 0;
    ObjectWrench unmoved;  // what a side that does not yield receives
    if (held) {
      // a held object goes with the hand; a free one it runs into meets it in its own
      // turn, but a sleeping one has none: woken, or met here where its turn has passed
      if (o == s || !yields || !other.asleep) return;
      if (o > s) {
        wake(other);
      } else if (contact_cache_.touch(o, other.generation, {&other.tree->tree, &other.def, other.def.mass}, s,
                                      slot.generation, {&slot.tree->tree, &slot.def, 0.0}, dt,
                                      &other.contact, &unmoved)) {
        wake(other);
      }
      return;
    }
    // itself, or a pair met from the other side (an awake object before this one)
    if (o == s || (yields && !other.asleep && o < s)) return;
    const bool touch = contact_cache_.touch(
        s, slot.generation, {&slot.tree->tree, &slot.def, slot.def.mass}, o, other.generation,
        {&other.tree->tree, &other.def, yields ? other.def.mass : 0.0}, dt, &slot.contact,
        yields ? &other.contact : &unmoved);
    // run into: it moves this step too. Not by one that is itself still (it rests on or
    // under the sleeper): a stack woke each other in turn for ever, never asleep together
    if (touch && yields && other.asleep && !(slot.still_for > 0.0)) wake(other);
  });
}

void SceneObjects::move_dynamic(Slot& slot, const vec3& gravity, double dt) {
  const double load = slot.def.mass * (glm::length(gravity) + kGraspMargin);
  const bool taken = slot.held_by < 0 && slot.offer_hand >= 0 && slot.offer_load >= load;
  if (taken) {
    slot.held_by = slot.offer_hand;
    slot.holder_palm = slot.offer_palm;
    slot.in_palm = relative_pose(slot.holder_palm, slot.def.pose);
  } else if (slot.held_by >= 0 && !(slot.holder_load >= kReleaseShare * load)) {
    slot.held_by = -1;  // let go: it keeps the hand's velocity, the pushes come back
    slot.pushes_share = 0.0;
  }
  slot.holder_load = slot.offer_load = 0.0;
  slot.offer_hand = -1;

  const ObjectWrench contact = slot.contact;
  slot.contact = ObjectWrench{};
  if (slot.asleep) return;
  if (slot.held_by < 0) {
    const ObjectWrench pushes{slot.pushes_share * slot.reaction.force + contact.force,
                              slot.pushes_share * slot.reaction.torque + contact.torque};
    advance_object(slot.def, pushes, gravity, dt);
    slot.pushes_share = std::min(1.0, slot.pushes_share + dt / kReleaseRamp);
    const bool still = glm::length(slot.def.linear_velocity) < kSleepSpeed &&
                       glm::length(slot.def.angular_velocity) < kSleepTurn;
    slot.still_for = still ? slot.still_for + dt : 0.0;
    if (slot.still_for >= kSleepSeconds) {
      slot.asleep = true;
      slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
    }
    return;
  }
  // held: rigidly in the palm, its velocities those of the move, and its reaction what
  // that move took (the carried mass's; the hand's pushes on it balance otherwise)
  const RigidPose& palm = slot.holder_palm;
  const RigidPose next{palm.position + palm.rotation * slot.in_palm.position,
                       palm.rotation * slot.in_palm.rotation};
  const vec3 velocity = (next.position - slot.def.pose.position) / dt;
  glm::dquat turn = glm::quat_cast(next.rotation * glm::transpose(slot.def.pose.rotation));
  if (turn.w < 0.0) turn = -turn;
  const vec3 axis(turn.x, turn.y, turn.z);
  const double sine = glm::length(axis);
  const vec3 spin = sine > 0.0 ? (2.0 * std::atan2(sine, turn.w) / (sine * dt)) * axis : vec3(0.0);
  slot.carried = {slot.def.mass * ((velocity - slot.def.linear_velocity) / dt - gravity), vec3(0.0)};
  slot.def.pose = next;
  slot.def.linear_velocity = velocity;
  slot.def.angular_velocity = spin;
}

}  // namespace frusta
