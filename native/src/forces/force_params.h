// SPDX-License-Identifier: MIT
// What the contact forces depend on (seed eqs. 12-13, [0083], [0166]): how an object's
// surface pushes back, and how much a glove can render.
#pragma once

#include "geometry/types.h"

namespace frusta {

// 1 mm of haptic penetration gives 0.4 N: a firm surface a glove can still render
// without buzzing. A placeholder until materials are tuned on a real device.
constexpr double kDefaultContactStiffness = 400.0;  // newtons per metre

// Beyond this a stiffness is a units mistake (N/mm given as N/m is 1000x, not 1e6x),
// and below it the force of any accepted gap (kMaxCoordinate) stays finite.
constexpr double kMaxContactStiffness = 1e9;  // newtons per metre

// How one object's surface pushes back.
struct ForceMaterial {
  // the diagonal of G in seed eq. 12, in the object's own frame (so an anisotropic
  // material turns with its object); newtons per metre
  vec3 normal_stiffness{kDefaultContactStiffness};
  double friction = 0.6;  // mu of seed eq. 13, dimensionless
  // the stick spring: how hard a patch resists sliding before it slips, newtons per
  // metre. Skin sticks within about a millimetre, and a pinch holds only if it does:
  // a 50 g ball pinched 3 mm deep slips out at 400 N/m and is carried within 2.5 mm at
  // 1e4 (world_forces_test)
  double tangential_stiffness = 1e4;
  // on the rate a patch sinks in (N s/m): 0 is seed eq. 12 exactly; a held object rings
  // on the contact springs without it. 2 sqrt(k m) damps an object of mass m critically
  double normal_damping = 0.0;
  // on the rate a sticking patch slides (N s/m): 0 is a pure spring. The stick spring
  // is stiff, so a hand jittering by a step's motion kicks a held object with it;
  // 2 sqrt(k_t m) damps an object of mass m critically
  double tangential_damping = 0.0;
};

// What a device can render; every output is scaled down to fit, never redirected.
// Placeholders of the order consumer force-feedback gloves render (around ten newtons
// at a fingertip, tenths of a newton-metre at a finger joint), not taken from any one
// datasheet: a device's driver sets its own.
struct DeviceLimits {
  double max_fingertip_force = 10.0;    // newtons, per finger
  double max_finger_resistance = 10.0;  // newtons, per finger
  double max_joint_torque = 0.5;        // newton-metres, per joint
  double max_palm_force = 20.0;         // newtons
  double max_palm_torque = 1.0;         // newton-metres, about the palm origin
};

}  // namespace frusta
