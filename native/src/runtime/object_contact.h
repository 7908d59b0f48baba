// SPDX-License-Identifier: MIT
// Contact between two objects: a dynamic object resting on a table, dropped onto it, or
// knocking another. The world had none (a marble let go of fell through the table).
//
// The model is one patch per pair of objects, as the hand's forces are one per patch
// (forces/normal_force.h): the overlapping leaf pairs of the two trees give a depth (the
// deepest pair's), a normal and a point (their depth-weighted means), so a body meets
// one surface however finely the trees cover it. The patch pushes as a spring-damper
// tuned to the pair's effective mass at the patch (turning included): natural frequency
// kObjectContactHz (or rate / 4 rad/s where that is lower) and critically damped, so
// any mass and shape settles without ringing, about g / omega^2 deep (0.28 mm at 30 Hz),
// and the step stays stable at any rate. Friction is a stick spring on how far the patch
// slid since it last slipped, tuned and damped alike, up to mu |F| (mu the geometric mean
// of the two materials'), beyond which it slips: an object stays where friction can hold
// it (a slope, a stack), stretching the spring g sin(theta) / omega^2 (5 um a degree of
// slope), and slides where it cannot. A relative turn (rolling, spinning) meets a
// damping up to kRollingLength |F|.
#pragma once

#include "forces/device_outputs.h"
#include "runtime/world_def.h"
#include "spheretree/sphere_tree.h"

namespace frusta {

constexpr double kObjectContactHz = 30.0;
constexpr double kRollingLength = 2e-4;  // metres

// One side of a pair: its tree, its state, and its mass (0: it does not yield, as a
// static object or one a hand holds; its velocities still count).
struct ContactSide {
  const SphereTree* tree = nullptr;
  const ObjectDef* def = nullptr;
  double mass = 0.0;
};

// The patch of a pair's overlapping leaves, summed in a's frame as they are found.
struct ContactPatchSums {
  double deepest = 0.0, weight = 0.0;
  vec3 normal_sum{0.0}, point_sum{0.0};
  // a pair of leaves (both in a's frame); nothing where they do not overlap
  void add(const Sphere& leaf_a, const Sphere& leaf_b);
};

// What a pair's patch keeps from one step to the next: how far it slid since it last
// slipped, the stretch of its stick spring (static friction), in a's frame. Zero for a
// pair that did not touch.
struct PatchStick {
  vec3 stretch{0.0};
};

// The wrenches a pair's patch puts on a and on b (each about its own pose position),
// added to *on_a and *on_b; dt is the world's time step (seconds); *stick is the pair's,
// brought up to date. Returns whether they touch. At least one side has a mass.
bool add_patch_wrench(const ContactPatchSums& patch, const ContactSide& a, const ContactSide& b,
                      double dt, PatchStick* stick, ObjectWrench* on_a, ObjectWrench* on_b);

// The same from a walk of both trees (runtime/contact_cache.h walks less often).
bool add_object_contact(const ContactSide& a, const ContactSide& b, double dt, PatchStick* stick,
                        ObjectWrench* on_a, ObjectWrench* on_b);

}  // namespace frusta
