// SPDX-License-Identifier: MIT
// Friction, seed eq. 13 made continuous, once per patch: a tangential spring stretched by
// how far the body (on the haptic hand) has moved over the object since the patch began
// (stick); where it would exceed mu |F| its stretch is cut back so that the friction is
// exactly mu |F| against the slip (slip: the seed's f = mu |F| t). The stretch is kept in
// the object's frame, so it rides with the object; leaves joining or leaving a patch as
// the hand moves over an object change nothing, so a carried object is not let go of.
#pragma once

#include <cstdint>

#include "forces/force_params.h"
#include "hand/kinematics.h"
#include "solver/detection.h"
#include "spheretree/sphere_tree.h"

namespace frusta {

// What a patch's friction keeps from step to step, in the object's frame.
struct FrictionAnchor {
  RigidPose body;     // the body's haptic frame
  vec3 stretch{0.0};  // the spring's, tangential
};

struct PatchFriction {
  vec3 force{0.0};  // on the hand, the whole patch's, newtons
  bool slipping = false;
  FrictionAnchor anchor;  // for the next step
};

// The frame a body's points are given in: the palm's, or a segment's at its proximal
// joint.
inline RigidPose haptic_body_frame(const HandPose& haptic, int32_t body) {
  if (body == kPalmBody) return {haptic.palm_position, haptic.palm_rotation};
  const FingerPose& f = haptic.fingers[body / FRUSTA_SEGMENTS_PER_FINGER];
  const int segment = body % FRUSTA_SEGMENTS_PER_FINGER;
  return {f.joint[segment], f.segment_rotation[segment]};
}

// Stick, then slip, once a spring's pull is known: `force` (the spring's pull `spring`,
// newtons, plus its damping) projected onto the disc of radius `limit` (mu |F|), and the
// stretch `held` cut back so that the spring alone pulls no more than that. A continuous
// function of the motion, equal on both sides of the switch, so there is no jump to
// chatter between; reversing the motion unloads the spring smoothly through zero.
// Returns whether it slips. The hands' patches and the objects' pairs both slip so.
bool slip_at_limit(double limit, double spring, vec3* force, vec3* held);

// A patch's friction this step. `body`: its body's frame on the haptic hand (from
// haptic_body_frame); `normal`: the patch's mean normal, unit; `reference`: a material
// point of the body (any would do); `normal_force`: the patch's total; `before`: its
// anchor from the last step, null where the patch is new; time_step in (0, 1] seconds.
PatchFriction patch_friction(const ForceMaterial& material, const RigidPose& object,
                             const RigidPose& body, const vec3& normal, const vec3& reference,
                             const vec3& normal_force, const FrictionAnchor* before,
                             double time_step);

}  // namespace frusta
