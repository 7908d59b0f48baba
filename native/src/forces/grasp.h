// SPDX-License-Identifier: MIT
// Whether a hand's pushes on an object squeeze it: a grasp condition, as VR interaction
// engines use one, that the world turns into a hold (runtime/scene_objects.h).
//
// Why a condition at all: each push is the contact spring's, stiffness x the depth the
// haptic hand reached (seed eq. 12). A closed power grasp reaches far deeper with the
// fingers than with the palm or thumb, so its pushes do not balance: on a ball under the
// palm the fingers' net push is tens of newtons, and the ball squirts out of a hand that
// holds it firmly. A squeezed object is held by the friction of pads that oppose each
// other; once that friction bears the object's load, it moves with the hand.
//
// The condition: two bodies of the hand (the palm, or finger segments) whose pushes on
// the object oppose (the angle between them at least kOppositionCos's) bear, by
// friction, 2 mu min(|F_a|, |F_b|) (-cos) of load: the squeeze the weaker pad answers,
// on both pads, along their common axis. Only the best pair counts: the sum of every
// push would overstate what a pinch holds (the stronger pad's excess pushes, it does not
// hold).
#pragma once

#include <array>

#include "forces/contact_forces.h"
#include "solver/detection.h"

namespace frusta {

// Pushes at an angle over ~104 degrees oppose: a thumb and a finger on a ball, fingers
// and palm around a handle.
constexpr double kOppositionCos = -0.25;

// A hand's pushes on one object, summed per body (normal forces on the hand; friction
// is what they bear, not what squeezes).
using BodyPushes = std::array<vec3, kBodyCount>;

// The load (newtons) the best opposing pair of `pushes` bears by friction `mu`; 0 where
// no two bodies oppose.
double squeeze_load(const BodyPushes& pushes, double mu);

}  // namespace frusta
