// SPDX-License-Identifier: MIT
// A step's contacts grouped into patches: the contacts of one body on one object (a
// fingertip on a face the tree covers with several leaves) are one surface to the hand.
// Each contact gets its haptic point P_ih (the graphic point P_ig as the same material
// point of the haptic hand) and a weight: how near it is (1 touching, fading to 0 at the
// contact distance) times how it presses (0 where P_ih lies outside, rising to 1 over
// half the contact distance of depth). A leaf joining or leaving a patch as the hand
// slides then turns its force continuously, and a face the graphic hand only touches
// (in a corner) turns nothing. Each patch gets the weighted sums its force is made of.
#pragma once

#include <cstdint>
#include <tuple>
#include <vector>

#include "hand/kinematics.h"
#include "solver/hand_solver.h"

namespace frusta {

// A patch's identity from step to step.
struct PatchKey {
  int32_t object = 0;
  int32_t body = 0;
};

// Key order: by object, then body.
inline bool precedes(const PatchKey& a, const PatchKey& b) {
  return std::tie(a.object, a.body) < std::tie(b.object, b.body);
}

// The point `point` of hand body `body` (finger * 3 + segment, or kPalmBody) as posed
// by `from`, where the same material point lies on the hand posed by `to`.
vec3 same_material_point(const HandPose& from, const HandPose& to, int32_t body, const vec3& point);

// One contact of a patch.
struct PatchContact {
  int32_t index = 0;       // into the contacts grouped
  vec3 haptic_point{0.0};  // P_ih, metres
  double press = 0.0;      // how it presses, in [0, 1]
  double weight = 0.0;     // how near, times press
};

// One patch: its contacts, and their weighted sums.
struct ContactPatch {
  PatchKey key;
  int32_t begin = 0, end = 0;  // its contacts in ContactPatches::contacts()
  double weight_sum = 0.0;
  double press_sum = 0.0;  // of the presses of contacts with a weight
  vec3 gap_sum{0.0};      // of the weighted gaps P_ig - P_ih
  vec3 normal_sum{0.0};   // of the weighted normals
  vec3 haptic_sum{0.0};   // of the weighted haptic points
};

class ContactPatches {
 public:
  // Reserves room for `capacity` contacts; nothing is allocated afterwards. Contacts fade
  // out over `contact_distance` metres of gap (>= 0), and in over half of it of depth.
  ContactPatches(int32_t capacity, double contact_distance);

  // Groups contacts[0, count) (count <= capacity, ids in range) of the graphic hand at
  // `graphic` into patches in key order, a patch's contacts in their given order; the
  // haptic points are on the haptic hand at `haptic`.
  void group(const HandPose& graphic, const HandPose& haptic, const SolverContact* contacts,
             int32_t count);

  const std::vector<PatchContact>& contacts() const { return contacts_; }
  const std::vector<ContactPatch>& patches() const { return patches_; }

 private:
  double contact_distance_;
  std::vector<int32_t> order_;  // the contacts' indices in patch order
  std::vector<PatchContact> contacts_;
  std::vector<ContactPatch> patches_;
};

}  // namespace frusta
