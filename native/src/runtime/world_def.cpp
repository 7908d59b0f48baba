// SPDX-License-Identifier: MIT
#include "runtime/world_def.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "forces/force_checks.h"
#include "runtime/object_dynamics.h"

namespace frusta {

namespace {

// a rotation whose columns are further than this from orthonormal was not meant as one
constexpr double kOrthonormalTolerance = 1e-6;

}  // namespace

frusta_result check_rigid_pose(const RigidPose& pose, const char* name) {
  char field[96];
  std::snprintf(field, sizeof field, "%s.position", name);
  if (frusta_result r = check_bounded(glm::value_ptr(pose.position), 3, kMaxCoordinate, field))
    return r;
  std::snprintf(field, sizeof field, "%s.rotation", name);
  if (frusta_result r = check_finite(glm::value_ptr(pose.rotation), 9, field)) return r;
  const glm::dmat3 gram = glm::transpose(pose.rotation) * pose.rotation;
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::fabs(gram[i][j] - (i == j ? 1.0 : 0.0)));
  if (worst > kOrthonormalTolerance || glm::determinant(pose.rotation) < 0.0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "%s is not a rotation (R^T R differs from I by %g, det %g)", field, worst,
                glm::determinant(pose.rotation));
  return FRUSTA_OK;
}

frusta_result check_object_def(const ObjectDef& def) {
  if (frusta_result r = check_rigid_pose(def.pose, "object pose")) return r;
  if (frusta_result r = check_force_material(def.material, "object material")) return r;
  if (frusta_result r = check_range(def.mass, kMinMass, kMaxMass, false, "object mass")) return r;
  for (int k = 0; k < 3; ++k)
    if (frusta_result r = check_range_named(def.inertia[k], kMinInertia, kMaxInertia, false,
                                            "object inertia[%d]", k))
      return r;
  // principal moments of a real body: each at most the sum of the other two
  for (int k = 0; k < 3; ++k) {
    const double others = def.inertia[(k + 1) % 3] + def.inertia[(k + 2) % 3];
    if (def.inertia[k] > others * (1.0 + 1e-9))
      return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                  "object inertia[%d] is %g kg m^2, more than the other two together (%g): no "
                  "body has such principal moments", k, def.inertia[k], others);
  }
  if (frusta_result r = check_bounded(glm::value_ptr(def.linear_velocity), 3, kMaxLinearSpeed,
                                      "object linear_velocity"))
    return r;
  if (frusta_result r = check_bounded(glm::value_ptr(def.angular_velocity), 3, kMaxAngularSpeed,
                                      "object angular_velocity"))
    return r;
  if (frusta_result r = check_range(def.linear_damping, 0.0, 1e3, false, "object linear_damping"))
    return r;
  return check_range(def.angular_damping, 0.0, 1e3, false, "object angular_damping");
}

frusta_result check_world_def(const WorldDef& def) {
  if (frusta_result r = check_range(def.rate_hz, 1.0, 100000.0, false, "rate_hz")) return r;
  // the solver's knobs a world exposes; the hand-dependent rules are checked when a
  // hand is added. The margin lies above the solver's penetration tolerance (1e-6 m).
  if (frusta_result r = check_range(def.solver.prediction_margin, 1e-5, 0.1, false,
                                    "prediction_margin"))
    return r;
  if (frusta_result r = check_range(def.solver.lod_error, 0.0, 1.0, false, "lod_error"))
    return r;
  if (def.solver.max_iterations < 1 || def.solver.max_iterations > 100)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_iterations is %d, must be 1..100",
                def.solver.max_iterations);
  if (def.solver.max_substeps < 1 || def.solver.max_substeps > 1024)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_substeps is %d, must be 1..1024",
                def.solver.max_substeps);
  if (frusta_result r = check_range(def.spin_us, 0.0, 1e6 / def.rate_hz, false, "spin_us"))
    return r;
  if (frusta_result r = check_bounded(glm::value_ptr(def.gravity), 3, 1e3, "gravity")) return r;
  if (def.max_objects < 1 || def.max_objects > 65535)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_objects is %d, must be 1..65535", def.max_objects);
  if (def.max_hands < 1 || def.max_hands > kMaxHands)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_hands is %d, must be 1..%d", def.max_hands, kMaxHands);
  if (def.solver.candidate_capacity < 1 || def.solver.candidate_capacity > kMaxCandidateCapacity)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_candidates_per_hand is %d, must be 1..%d",
                def.solver.candidate_capacity, kMaxCandidateCapacity);
  if (def.max_contacts_per_hand < 0 || def.max_contacts_per_hand > 65536)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_contacts_per_hand is %d, must be 0..65536",
                def.max_contacts_per_hand);
  if (def.command_capacity < 1 || def.command_capacity > 1 << 20)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "command_capacity is %d, must be 1..2^20",
                def.command_capacity);
  if (frusta_result r = check_range(def.input_delay, 0.0, kMaxInputDelay, false, "input_delay"))
    return r;
  if (frusta_result r = check_range(def.max_extrapolation, 0.0, kMaxInputDelay, false,
                                    "max_extrapolation"))
    return r;
  return check_device_limits(def.device_limits);
}

}  // namespace frusta
