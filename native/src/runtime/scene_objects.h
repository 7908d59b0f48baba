// SPDX-License-Identifier: MIT
// The stepping side of a world's objects: one slot per object id (tree, pose,
// velocities, this step's reaction), and the list of present objects the hands solve
// against, rebuilt only when a command changed it. Everything is sized when the world
// is built: a step allocates nothing. A step's own work is in proportion to the objects
// it touches or moves, not to the slots: a room of resting props costs it nothing
// (issue 21), so reactions, placings, dynamics and the snapshot's copies each keep a
// list of the slots they concern.
//
// Threads: the stepping thread only.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/device_outputs.h"
#include "runtime/world_command.h"
#include "runtime/world_snapshot.h"
#include "solver/broad_phase.h"
#include "solver/hand_solver.h"

namespace frusta {

class SceneObjects final : public ObjectFinder {
 public:
  explicit SceneObjects(int32_t capacity);

  // The present objects (indices into active()) whose bounds may meet `box`, from a
  // broad phase over their world bounds (solver/broad_phase.h): a hand's solver looks
  // at these instead of at every object.
  int32_t find(const Aabb& box, int32_t* out, int32_t capacity) const override;

  // One queued object command, as the host side made it. Returns whether the present
  // list must be rebuilt (an object came or went); a pose is changed in it in place.
  bool apply(const WorldCommand& command);
  // The present objects again, after commands changed them.
  void rebuild_active();

  // The present objects, and for each its slot and material (index-aligned).
  const std::vector<SolverObject>& active() const { return active_; }
  const std::vector<int32_t>& active_slot() const { return active_slot_; }
  const std::vector<ForceMaterial>& active_material() const { return active_material_; }
  // Whether the host added or moved the object in `slot` since the last end_step().
  bool placed(int32_t slot) const { return placed_[static_cast<size_t>(slot)] != 0; }
  // The slots placed since the last end_step(), and a slot's index in active() (-1: empty).
  const std::vector<int32_t>& placed_slots() const { return placed_list_; }
  int32_t active_index(int32_t slot) const { return active_index_[static_cast<size_t>(slot)]; }
  // Whether the present list was rebuilt, or its poses moved, since the last end_step().
  bool moved() const { return moved_; }

  // Which hands ignore the object in `slot` (hand_pipeline.h), as each hand finds it
  // inside itself or leaves it; a removed hand ignores nothing.
  void set_ignored(int32_t slot, int32_t hand, bool ignored);
  void forget_hand(int32_t hand);

  // The hands' reactions: cleared at each step's start, summed as hands are solved.
  void clear_reactions();
  void add_reaction(int32_t slot, const ObjectWrench& wrench);

  // Every slot as the hands met it, into snapshot (one entry per slot), the one of
  // `buffer` (0..2) of the world's triple buffer: only the slots changed since that
  // buffer was last filled are copied.
  void publish(std::vector<ObjectSnapshot>& snapshot, int buffer);
  // Move the dynamic objects by dt (object_dynamics.h) and forget this step's placings.
  void end_step(const vec3& gravity, double dt);

 private:
  struct Slot {
    const TreeFile* tree = nullptr;  // null: empty
    uint32_t generation = 0;
    ObjectDef def;          // pose and velocities as the world moves it
    ObjectWrench reaction;  // this step's, from every hand
    uint64_t ignored_by = 0;  // bit h: the hand in slot h
  };

  // the slot's snapshot entry changed: each of the three buffers copies it when next filled
  void changed(int32_t slot);
  // the slot's object appeared, went or moved: its leaf in the broad phase follows
  void track(int32_t slot);

  std::vector<Slot> slots_;
  std::vector<int32_t> active_index_;  // per slot: its index in active_, or -1
  BroadPhase broad_phase_;             // the present objects with a non-empty tree
  std::vector<int32_t> proxy_;         // per slot: its leaf there, or BroadPhase::kNull
  std::vector<int32_t> stale_[3];      // per buffer: the slots it has not seen change
  std::vector<uint8_t> stale_in_;      // per slot: bit b, listed in stale_[b]
  std::vector<uint8_t> reacted_in_;    // per slot: listed in reacted_
  std::vector<int32_t> reacted_;       // slots given a reaction this step
  std::vector<int32_t> placed_list_;   // slots with placed_ set
  std::vector<int32_t> dynamic_;       // present dynamic slots, in slot order
  std::vector<SolverObject> active_;
  std::vector<int32_t> active_slot_;
  std::vector<ForceMaterial> active_material_;
  std::vector<uint8_t> placed_;
  bool moved_ = false;
};

}  // namespace frusta
