// SPDX-License-Identifier: MIT
// The force at each contact between the graphic hand and an object (seed [0160]-[0165]).
// P_ig is the touching point on the graphic hand, P_ih the same material point on the
// haptic hand (the glove), n the unit normal from the object towards the hand. A step
// groups the contacts into patches (forces/contact_patches.h), gives each pressing patch
// its normal force (forces/normal_force.h) and its friction (forces/friction.h), shared
// among its contacts by weight. Patches keep their friction from step to step in a
// table sized once; a step allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/contact_patches.h"
#include "forces/force_checks.h"
#include "forces/force_params.h"
#include "forces/friction.h"
#include "hand/kinematics.h"
#include "solver/hand_solver.h"

namespace frusta {

// Contacts a hand's table holds by default: as many as the world keeps per hand.
constexpr int32_t kDefaultForceContactCapacity = 256;

// The force on the hand at one contact, in world coordinates.
struct ContactForce {
  int32_t object = 0;  // as in SolverContact
  int32_t leaf = 0;
  int32_t body = 0;
  int32_t part = 0;
  vec3 graphic_point{0.0};  // P_ig: where hand and object meet, metres
  vec3 haptic_point{0.0};   // P_ih: the same material point on the haptic hand, metres
  vec3 normal{0.0};         // unit, from the object towards the hand
  vec3 normal_force{0.0};   // F of seed eq. 12, on the hand, newtons
  vec3 friction{0.0};       // f, on the hand, newtons
  bool slipping = false;    // pressing, and its patch slid this step
};

struct ContactForceStats {
  int32_t pressing = 0;  // contacts sharing a patch's push: its gap points out of the object
  int32_t slipping = 0;
  int32_t dropped = 0;  // contacts beyond the table's capacity, left out this step
  int32_t held_back = 0;  // patches whose push the lag limit held back (or faded out)
  double held_back_by = 0.0;  // newtons: the most a push was held back from its own
};

class ContactForces {
 public:
  // Reserves room for `capacity` contacts (a negative count is 0); nothing is allocated
  // afterwards. `contact_distance` (>= 0): the solver's (SolverParams), over which a
  // contact's share fades out.
  explicit ContactForces(int32_t capacity = kDefaultForceContactCapacity,
                         double contact_distance = SolverParams{}.contact_distance);

  // One step: the forces at `contacts` (a HandSolver's contacts() after its step), the
  // graphic hand at `graphic` (its graphic_pose()) and the haptic hand at `haptic` (its
  // target_pose()). `objects` are the solver's objects, `materials` one per object (null:
  // ForceMaterial{} for all). The first `capacity` contacts in the solver's order are
  // kept, the rest counted in stats->dropped. stats may be null.
  //
  // `lagging`: the solver's step ended short of its target (StepStats::lagging). Its
  // graphic hand is then behind the haptic one and a push worked out from it carries the
  // lag (a contact that the catching-up hand makes or breaks in one step would jump by
  // stiffness x lag), so from such a step until every push is its own again each patch's
  // push changes a step by at most its stiffness times the move of its haptic point plus
  // kLagForceSlack, and a patch that vanished fades out at that rate, applied at its last
  // haptic point (an entry of forces() past the contacts', leaf -1).
  static constexpr double kLagForceSlack = 0.02;  // newtons a step
  // Preconditions, which the solver's and the world's output meet and debug builds
  // assert: counts >= 0; both poses pass check_hand_pose, the contacts
  // check_solver_contacts, the objects and materials check_force_objects.
  void update(const HandPose& graphic, const HandPose& haptic, const SolverContact* contacts,
              int32_t contact_count, const SolverObject* objects, int32_t object_count,
              const ForceMaterial* materials, ContactForceStats* stats, bool lagging = false);

  // Forget every patch (e.g. after a teleport): the next step starts every friction at 0.
  void reset();

  // The time between updates (seconds, in (0, 1]), for the damping's sink rate; 1 ms
  // unless set.
  frusta_result set_time_step(double seconds);

  // The last step's forces, in the order of its contacts, then the fading pushes of
  // patches that vanished while the lag limit held (see update).
  const std::vector<ContactForce>& forces() const { return forces_; }

 private:
  // A patch as the next step needs it.
  struct Patch {
    PatchKey key;
    FrictionAnchor friction;
    double depth;  // PatchPress::depth, metres
    vec3 push;     // the normal force it gave, newtons
    vec3 point;    // its mean haptic point, metres
    vec3 normal;   // unit
  };

  // A push `want` for a patch that gave `had`, its haptic point moved from `from` (on the
  // last step's haptic hand) to `to`, within the lag limit; `held` is set when it binds.
  vec3 limit(const ForceMaterial& material, const vec3& had, const vec3& want, const vec3& from,
             const vec3& to, ContactForceStats& stats) const;
  // A patch of the last step absent from this one: while the lag limit holds, its push
  // fades out at the limit's rate as an entry of forces_ and it is kept for the next step.
  void fade(const Patch& gone, const HandPose& haptic, const ForceMaterial& material,
            int32_t object_count, ContactForceStats& stats);

  int32_t capacity_;
  double time_step_ = 1e-3;
  bool limiting_ = false;  // the lag limit holds (update)
  HandPose last_haptic_;   // the last step's haptic hand: how far a patch's point moved
  ContactPatches grouping_;          // this step's contacts by patch
  std::vector<Patch> patches_;       // sorted by key: the last step's
  std::vector<Patch> next_patches_;  // being built; swapped in at the end of a step
  std::vector<ContactForce> forces_;
};

}  // namespace frusta
