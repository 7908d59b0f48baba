// SPDX-License-Identifier: MIT
// A step's contacts grouped into patches: the contacts of one body on one object (a
// fingertip on a face the tree covers with several leaves) are one surface to the hand.
// Each contact gets its haptic point P_ih (the graphic point P_ig as the same material
// point of the haptic hand) and its depth (P_ig - P_ih) . n, pressing when > 0; each
// patch what its pressing contacts add up to, which its forces share out.
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

// One contact of a patch.
struct PatchContact {
  int32_t index = 0;       // into the contacts grouped
  vec3 haptic_point{0.0};  // P_ih, metres
  double depth = 0.0;      // (P_ig - P_ih) . n, metres; pressing when > 0
};

// One patch: its contacts, and sums over those that press.
struct ContactPatch {
  PatchKey key;
  int32_t begin = 0, end = 0;  // its contacts in ContactPatches::contacts()
  int32_t pressing = 0;
  vec3 haptic_sum{0.0};  // of the pressing contacts' haptic points
  vec3 normal_sum{0.0};
  double depth_sum = 0.0;
};

class ContactPatches {
 public:
  // Reserves room for `capacity` contacts; nothing is allocated afterwards.
  explicit ContactPatches(int32_t capacity);

  // Groups contacts[0, count) (count <= capacity, ids in range) of the graphic hand at
  // `graphic` into patches in key order, a patch's contacts in their given order; the
  // haptic points are on the haptic hand at `haptic`.
  void group(const HandPose& graphic, const HandPose& haptic, const SolverContact* contacts,
             int32_t count);

  const std::vector<PatchContact>& contacts() const { return contacts_; }
  const std::vector<ContactPatch>& patches() const { return patches_; }

 private:
  std::vector<int32_t> order_;  // the contacts' indices in patch order
  std::vector<PatchContact> contacts_;
  std::vector<ContactPatch> patches_;
};

}  // namespace frusta
