// SPDX-License-Identifier: MIT
// How the world moves a dynamic object: one semi-implicit Euler step under the hands'
// reaction and gravity, as a free function over the object's state.
#pragma once

#include "forces/device_outputs.h"
#include "geometry/types.h"
#include "runtime/world_def.h"

namespace frusta {

// A dynamic object faster than these has been flung by a bug or absurd input: capped,
// so that it stays a finite pose the solver can meet. Also the ranges of an object
// def's velocities.
constexpr double kMaxLinearSpeed = 100.0;    // m/s
constexpr double kMaxAngularSpeed = 1000.0;  // rad/s

// Advance `object` (its pose and velocities) by dt seconds under `reaction` (the
// hands' wrench about its centre of mass) and gravity; damping and the speed caps
// applied, and stopped at the world's edge (kMaxCoordinate).
void advance_object(ObjectDef& object, const ObjectWrench& reaction, const vec3& gravity,
                    double dt);

}  // namespace frusta
