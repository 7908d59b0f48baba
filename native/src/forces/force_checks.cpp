// SPDX-License-Identifier: MIT
#include "forces/force_checks.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "solver/detection.h"

namespace frusta {

namespace {

// a normal further than this from unit length was not made by the solver
constexpr double kUnitTolerance = 1e-6;

frusta_result check_contact(const SolverContact& c, int32_t i, int32_t object_count) {
  if (frusta_result r = check_contact_ids(c.object, c.body, object_count, "contacts", i)) return r;
  if (c.leaf < -1 || c.part < 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "contacts[%d] has leaf %d and part %d; a leaf is >= -1, a part >= 0", i, c.leaf,
                c.part);
  if (!std::isfinite(c.distance))
    return fail(FRUSTA_ERROR_NOT_FINITE, "contacts[%d].distance is %g", i, c.distance);
  if (frusta_result r = check_bounded_named(glm::value_ptr(c.hand_point), 3, kMaxPointCoordinate,
                                            "contacts[%d].hand_point", i))
    return r;
  if (frusta_result r = check_bounded_named(glm::value_ptr(c.object_point), 3, kMaxPointCoordinate,
                                            "contacts[%d].object_point", i))
    return r;
  if (frusta_result r =
          check_bounded_named(glm::value_ptr(c.normal), 3, 2.0, "contacts[%d].normal", i))
    return r;
  const double length = glm::length(c.normal);
  if (std::fabs(length - 1.0) > kUnitTolerance)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contacts[%d].normal has length %g, must be unit", i,
                length);
  return FRUSTA_OK;
}

}  // namespace

frusta_result check_force_material(const ForceMaterial& m, const char* name) {
  for (int k = 0; k < 3; ++k)
    if (frusta_result r = check_range_named(m.normal_stiffness[k], 0.0, kMaxContactStiffness, false,
                                            "%s.normal_stiffness[%d]", name, k))
      return r;
  if (frusta_result r = check_range_named(m.tangential_stiffness, 0.0, kMaxContactStiffness, false,
                                          "%s.tangential_stiffness", name))
    return r;
  if (frusta_result r = check_range_named(m.normal_damping, 0.0, kMaxContactStiffness, false,
                                          "%s.normal_damping", name))
    return r;
  if (frusta_result r = check_range_named(m.tangential_damping, 0.0, kMaxContactStiffness, false,
                                          "%s.tangential_damping", name))
    return r;
  // a friction coefficient above a few is not a material but a typo; 100 leaves room
  return check_range_named(m.friction, 0.0, 100.0, false, "%s.friction", name);
}

frusta_result check_hand_pose(const HandPose& pose, const char* which) {
  if (frusta_result r = check_bounded_named(glm::value_ptr(pose.palm_position), 3, kMaxCoordinate,
                                            "%s pose palm_position", which))
    return r;
  if (frusta_result r =
          check_finite_named(glm::value_ptr(pose.palm_rotation), 9, "%s pose palm_rotation", which))
    return r;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPose& finger = pose.fingers[f];
    for (size_t j = 0; j < finger.joint.size(); ++j)
      if (frusta_result r = check_bounded_named(glm::value_ptr(finger.joint[j]), 3, kMaxPointCoordinate,
                                                "%s pose finger %d joint %zu", which, f, j))
        return r;
    for (size_t s = 0; s < finger.segment_rotation.size(); ++s)
      if (frusta_result r =
              check_finite_named(glm::value_ptr(finger.segment_rotation[s]), 9,
                                 "%s pose finger %d segment_rotation %zu", which, f, s))
        return r;
    if (frusta_result r = check_finite_named(glm::value_ptr(finger.abduction_axis), 3,
                                             "%s pose finger %d abduction axis", which, f))
      return r;
    if (frusta_result r = check_finite_named(glm::value_ptr(finger.flexion_axis), 3,
                                             "%s pose finger %d flexion axis", which, f))
      return r;
  }
  return FRUSTA_OK;
}

frusta_result check_contact_ids(int32_t object, int32_t body, int32_t object_count,
                                const char* what, int32_t index) {
  if (object < 0 || object >= object_count)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s[%d].object is %d, must be in [0, %d)", what, index,
                object, object_count);
  if (body < 0 || body >= kBodyCount)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s[%d].body is %d, must be in [0, %d]", what, index,
                body, kPalmBody);
  return FRUSTA_OK;
}

frusta_result check_solver_contacts(const SolverContact* contacts, int32_t count,
                                    int32_t object_count) {
  for (int32_t i = 0; i < count; ++i)
    if (frusta_result r = check_contact(contacts[i], i, object_count)) return r;
  return FRUSTA_OK;
}

frusta_result check_force_objects(const SolverObject* objects, int32_t count,
                                  const ForceMaterial* materials) {
  for (int32_t o = 0; o < count; ++o) {
    if (frusta_result r = check_bounded_named(glm::value_ptr(objects[o].pose.position), 3,
                                              kMaxCoordinate, "objects[%d].pose.position", o))
      return r;
    if (frusta_result r = check_finite_named(glm::value_ptr(objects[o].pose.rotation), 9,
                                             "objects[%d].pose.rotation", o))
      return r;
    if (!materials) continue;
    char name[32];
    std::snprintf(name, sizeof name, "materials[%d]", o);
    if (frusta_result r = check_force_material(materials[o], name)) return r;
  }
  return FRUSTA_OK;
}

}  // namespace frusta
