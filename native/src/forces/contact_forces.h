// SPDX-License-Identifier: MIT
// The force at each contact between the graphic hand and an object (seed [0160]-[0165]).
// P_ig is the touching point on the graphic hand, P_ih the same material point on the
// haptic hand (the glove), n the unit normal from the object towards the hand.
//  - normal force, seed eq. 12: F = G n |P_ig - P_ih| while P_ih lies inside, i.e.
//    (P_ig - P_ih) . n > 0, and 0 otherwise; where k contacts press one body on one
//    object (a fingertip on a face of many leaves) each takes G / k, so a body feels
//    one surface however finely the tree covers it;
//  - friction, seed eq. 13 made continuous: each contact keeps an anchor on its object
//    (riding with it); the friction is a spring from the anchor to P_ih in the tangent
//    plane (stick), and where that spring would exceed mu |F| the anchor is dragged
//    along so that the friction is exactly mu |F| against the slip (slip: the seed's
//    f = mu |F| t).
// Contacts keep their anchors from step to step in a table sized once; a step allocates
// nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/force_params.h"
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
  bool slipping = false;    // pressing, and the anchor was dragged this step
};

struct ContactForceStats {
  int32_t pressing = 0;  // contacts whose haptic point lies inside: (P_ig - P_ih) . n > 0
  int32_t slipping = 0;
  int32_t dropped = 0;  // contacts beyond the table's capacity, left out this step
};

// The haptic hand's pose as the solver aims at it (HandSolver::step does the same):
// rotation normalised and angles clamped to the model's limits, so that where nothing
// is touched both hands coincide and a glove reading past a joint limit makes no force.
// `haptic` must be a state HandSolver::step accepted.
void haptic_hand_pose(const HandModel& model, const HandState& haptic, HandPose& pose);

// Every position, frame and axis of a pose finite, positions within kMaxCoordinate;
// the thread's error names `which` and the field. Shared with the device outputs.
frusta_result check_hand_pose(const HandPose& pose, const char* which);

class ContactForces {
 public:
  // Reserves room for `capacity` contacts (a negative count is 0); nothing is allocated
  // afterwards.
  explicit ContactForces(int32_t capacity = kDefaultForceContactCapacity);

  // One step: the forces at `contacts` (a HandSolver's contacts() after its step), the
  // graphic hand at `graphic` (its graphic_pose()) and the haptic hand at `haptic`
  // (haptic_hand_pose of the state given to that step). `objects` are the solver's
  // objects, `materials` one per object (null: ForceMaterial{} for all). The first
  // `capacity` contacts in the solver's order are kept, the rest counted in stats->dropped.
  // Bad input (non-finite, an object or body out of range, a bad material) returns an
  // error and leaves the forces and every anchor as they were. stats may be null.
  frusta_result update(const HandPose& graphic, const HandPose& haptic,
                       const SolverContact* contacts, int32_t contact_count,
                       const SolverObject* objects, int32_t object_count,
                       const ForceMaterial* materials, ContactForceStats* stats);

  // Forget every anchor (e.g. after a teleport): the next step starts every friction at 0.
  void reset();

  // The last successful step's forces, in the order of its contacts.
  const std::vector<ContactForce>& forces() const { return forces_; }

 private:
  // A contact's identity from step to step. Several inner nodes standing in for their
  // leaves (leaf -1) can touch one body at once; `ordinal` numbers contacts that share
  // the rest of the key in the solver's order, so each keeps its own anchor.
  struct Key {
    int32_t object, body, part, leaf, ordinal;
  };
  struct Anchor {
    Key key;
    vec3 local;  // on the object, in the object's frame: it rides with the object
  };
  struct Slot {
    Key key;
    int32_t contact;  // index into this step's contacts
  };
  // a contact's haptic point and its share of its body's stiffness, worked out before
  // any force: the share needs every contact on the body
  struct Prepared {
    vec3 haptic_point{0.0};
    bool pressing = false;  // (P_ig - P_ih) . n > 0
    double share = 1.0;     // 1 / the contacts pressing the same body on the same object
  };
  static bool precedes(const Key& a, const Key& b);

  int32_t capacity_;
  std::vector<Slot> order_;           // this step's contacts sorted by key
  std::vector<Anchor> anchors_;       // sorted by key: the last step's contacts
  std::vector<Anchor> next_anchors_;  // being built; swapped in at the end of a step
  std::vector<ContactForce> forces_;
  std::vector<Prepared> prepared_;  // per entry of order_
};

}  // namespace frusta
