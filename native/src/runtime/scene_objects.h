// SPDX-License-Identifier: MIT
// The stepping side of a world's objects: one slot per object id (tree, pose,
// velocities, this step's reaction), and the list of present objects the hands solve
// against, rebuilt only when a command or the dynamics changed it. Everything is
// sized when the world is built: a step allocates nothing.
//
// Threads: the stepping thread only.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/device_outputs.h"
#include "runtime/world_command.h"
#include "runtime/world_snapshot.h"
#include "solver/hand_solver.h"

namespace frusta {

class SceneObjects {
 public:
  explicit SceneObjects(int32_t capacity);

  // One queued object command, as the host side made it.
  void apply(const WorldCommand& command);
  // The present objects again, after commands or motion changed them.
  void rebuild_active();

  // The present objects, and for each its slot and material (index-aligned).
  const std::vector<SolverObject>& active() const { return active_; }
  const std::vector<int32_t>& active_slot() const { return active_slot_; }
  const std::vector<ForceMaterial>& active_material() const { return active_material_; }
  // Whether the host added or moved the object in `slot` since the last end_step().
  bool placed(int32_t slot) const { return placed_[static_cast<size_t>(slot)] != 0; }
  // Whether the present list was rebuilt since the last end_step().
  bool moved() const { return moved_; }

  // Which hands ignore the object in `slot` (hand_pipeline.h), as each hand finds it
  // inside itself or leaves it; a removed hand ignores nothing.
  void set_ignored(int32_t slot, int32_t hand, bool ignored);
  void forget_hand(int32_t hand);

  // The hands' reactions: cleared at each step's start, summed as hands are solved.
  void clear_reactions();
  void add_reaction(int32_t slot, const ObjectWrench& wrench);

  // Every slot as the hands met it, into snapshot (one entry per slot).
  void publish(std::vector<ObjectSnapshot>& snapshot) const;
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

  std::vector<Slot> slots_;
  std::vector<SolverObject> active_;
  std::vector<int32_t> active_slot_;
  std::vector<ForceMaterial> active_material_;
  std::vector<uint8_t> placed_;
  bool moved_ = false;
};

}  // namespace frusta
