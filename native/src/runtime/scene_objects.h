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
#include "runtime/contact_cache.h"
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

  // Holds (forces/grasp.h). A dynamic object whose squeeze by one hand bears its load,
  // mass x (|gravity| + kGraspMargin), is held by that hand: it moves rigidly with the
  // hand's haptic palm (the user's) instead of under the pushes (which do not balance), until the
  // holder's squeeze bears less than kReleaseShare of that load (the share keeps a
  // grasp from flickering). Let go, it starts with the hand's velocity and the hands'
  // pushes on it come back over kReleaseRamp seconds, so that fingers still pressing
  // deep do not fling it. The glove feels the pushes either way.
  static constexpr double kGraspMargin = 2.0;    // m/s^2 of carrying on top of gravity
  static constexpr double kReleaseShare = 0.5;
  static constexpr double kReleaseRamp = 0.1;    // seconds
  // Rest (see Slot::asleep): below both speeds for this long, a dynamic object sleeps.
  static constexpr double kSleepSeconds = 0.3;
  static constexpr double kSleepSpeed = 1e-3;  // m/s
  static constexpr double kSleepTurn = 0.02;   // rad/s
  bool dynamic(int32_t slot) const {
    const Slot& s = slots_[static_cast<size_t>(slot)];
    return s.tree && s.def.dynamic;
  }
  // The squeeze of `hand` on the dynamic object in `slot` this step: the load it bears
  // (squeeze_load, newtons) and the hand's haptic palm.
  void offer_grasp(int32_t slot, int32_t hand, double load, const RigidPose& palm);
  // The hand holding the object in `slot`, or -1.
  int32_t held_by(int32_t slot) const { return slots_[static_cast<size_t>(slot)].held_by; }

  // Every slot as the hands met it, into snapshot (one entry per slot), the one of
  // `buffer` (0..2) of the world's triple buffer: only the slots changed since that
  // buffer was last filled are copied.
  void publish(std::vector<ObjectSnapshot>& snapshot, int buffer);
  // Move the dynamic objects by dt (object_dynamics.h) and forget this step's placings.
  void end_step(const vec3& gravity, double dt);

  // Object pairs whose contact was walked, and answered from the cache (contact_cache.h).
  int64_t contact_walks() const { return contact_cache_.walks(); }
  int64_t contact_reuses() const { return contact_cache_.reuses(); }

 private:
  struct Slot {
    const TreeFile* tree = nullptr;  // null: empty
    uint32_t generation = 0;
    ObjectDef def;          // pose and velocities as the world moves it
    ObjectWrench reaction;  // this step's, from every hand
    uint64_t ignored_by = 0;  // bit h: the hand in slot h
    // a hold: the holding hand (-1: none) and the object's pose in its haptic palm's frame
    int32_t held_by = -1;
    RigidPose in_palm;
    double pushes_share = 1.0;  // of the hands' reaction that moves it: < 1 just after a hold
    ObjectWrench carried;       // while held: what carrying it took (its reaction, published)
    ObjectWrench contact;       // this step's from other objects (object_contact.h)
    // at rest: a dynamic object that stayed still for kSleepSeconds is neither moved nor
    // touched against others until something wakes it (a hand's push, a host command,
    // an object that runs into it)
    bool asleep = false;
    double still_for = 0.0;  // seconds
    // this step's squeezes: the holder's, and the best other hand's
    double holder_load = 0.0;
    RigidPose holder_palm;
    int32_t offer_hand = -1;
    double offer_load = 0.0;
    RigidPose offer_palm;
  };

  // the slot's snapshot entry changed: each of the three buffers copies it when next filled
  void changed(int32_t slot);
  // the slot's object appeared, went or moved: its leaf in the broad phase follows
  void track(int32_t slot);
  // one step of a dynamic object: held, taken hold of, let go, or free; then whether it
  // falls asleep
  void move_dynamic(Slot& slot, const vec3& gravity, double dt);
  static void wake(Slot& slot) {
    slot.asleep = false;
    slot.still_for = 0.0;
  }
  // the contacts of the dynamic object in `slot` with the objects its bounds meet, added
  // to both sides' contact wrench (a pair of dynamic objects once)
  void touch_objects(int32_t slot, double dt);

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
  ContactCache contact_cache_;  // the dynamic objects' contacts with others
};

}  // namespace frusta
