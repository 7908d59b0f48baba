// SPDX-License-Identifier: MIT
#include "forces/device_outputs.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

// Above anything ContactForces makes (stiffness below 1e9 N/m, gaps below 4e6 m, mu
// below 100: under 1e18 N); it keeps every sum and torque here finite.
constexpr double kMaxContactForce = 1e20;  // newtons

frusta_result check_vector(const vec3& v, double limit, const char* name, int32_t index) {
  return check_bounded_named(glm::value_ptr(v), 3, limit, "forces[%d].%s", index, name);
}

frusta_result check_force(const ContactForce& c, int32_t i, int32_t object_count) {
  if (frusta_result r = check_contact_ids(c.object, c.body, object_count, "forces", i)) return r;
  if (frusta_result r = check_vector(c.graphic_point, kMaxPointCoordinate, "graphic_point", i)) return r;
  if (frusta_result r = check_vector(c.haptic_point, kMaxPointCoordinate, "haptic_point", i)) return r;
  if (frusta_result r = check_vector(c.normal_force, kMaxContactForce, "normal_force", i)) return r;
  return check_vector(c.friction, kMaxContactForce, "friction", i);
}

// v itself, or v shortened to `limit`: the device renders less, never elsewhere
vec3 clamp_length(const vec3& v, double limit) {
  const double length = glm::length(v);
  return length > limit ? v * (limit / length) : v;
}

}  // namespace

frusta_result check_device_limits(const DeviceLimits& l) {
  const double any = kMaxDeviceLimit;
  if (frusta_result r = check_range(l.max_fingertip_force, 0.0, any, false, "max_fingertip_force"))
    return r;
  if (frusta_result r =
          check_range(l.max_finger_resistance, 0.0, any, false, "max_finger_resistance"))
    return r;
  if (frusta_result r = check_range(l.max_joint_torque, 0.0, any, false, "max_joint_torque"))
    return r;
  if (frusta_result r = check_range(l.max_palm_force, 0.0, any, false, "max_palm_force")) return r;
  return check_range(l.max_palm_torque, 0.0, any, false, "max_palm_torque");
}

frusta_result check_contact_forces(const ContactForce* forces, int32_t count,
                                   int32_t object_count) {
  for (int32_t i = 0; i < count; ++i)
    if (frusta_result r = check_force(forces[i], i, object_count)) return r;
  return FRUSTA_OK;
}

void compute_device_outputs(const HandPose& haptic, const ContactForce* forces, int32_t force_count,
                            const SolverObject* objects, [[maybe_unused]] int32_t object_count,
                            const DeviceLimits& limits, DeviceOutputs* out,
                            ObjectWrench* reactions) {
  assert(out && force_count >= 0 && object_count >= 0 && (object_count == 0 || reactions));
  assert(check_device_limits(limits) == FRUSTA_OK);
  assert(check_hand_pose(haptic, "haptic") == FRUSTA_OK);
  assert(check_force_objects(objects, object_count, nullptr) == FRUSTA_OK);
  assert(check_contact_forces(forces, force_count, object_count) == FRUSTA_OK);

  // each contact's force acts on the haptic hand (the user's) at its haptic point
  DeviceOutputs result{};
  std::array<vec3, FRUSTA_FINGER_COUNT> finger_force{};
  // only the objects the forces name: a room of a thousand props costs nothing here
  for (int32_t i = 0; i < force_count; ++i) reactions[forces[i].object] = ObjectWrench{};
  for (int32_t i = 0; i < force_count; ++i) {
    const ContactForce& c = forces[i];
    const vec3 total = c.normal_force + c.friction;

    // the object receives the opposite force where it touches the graphic hand
    ObjectWrench& reaction = reactions[c.object];
    reaction.force -= total;
    reaction.torque += glm::cross(c.graphic_point - objects[c.object].pose.position, -total);

    if (c.body == kPalmBody) {
      result.palm_force += total;
      result.palm_torque += glm::cross(c.haptic_point - haptic.palm_position, total);
      continue;
    }
    const int finger = c.body / FRUSTA_SEGMENTS_PER_FINGER;
    const int segment = c.body % FRUSTA_SEGMENTS_PER_FINGER;
    finger_force[finger] += total;
    if (segment == FRUSTA_SEGMENTS_PER_FINGER - 1) result.fingertip_force[finger] += total;
    // virtual work: a joint's torque is the force along the point's motion per radian
    double jacobian[3 * kJacobianColumns];
    point_jacobian(haptic, finger, segment, c.haptic_point, jacobian);
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
      result.joint_torque[finger * FRUSTA_JOINTS_PER_FINGER + j] +=
          jacobian[j] * total.x + jacobian[kJacobianColumns + j] * total.y +
          jacobian[2 * kJacobianColumns + j] * total.z;
  }

  // the device's limits: each output scaled down as a whole, so it keeps its direction
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    result.fingertip_force[f] = clamp_length(result.fingertip_force[f], limits.max_fingertip_force);
    result.finger_resistance[f] =
        std::min(glm::length(finger_force[f]), limits.max_finger_resistance);
    // one factor for the finger's four joints: clamping each alone would change the
    // ratios between them, and so the way the finger is pushed
    double* tau = &result.joint_torque[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER)];
    double largest = 0.0;
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
      largest = std::max(largest, std::fabs(tau[j]));
    if (largest > limits.max_joint_torque) {
      const double scale = limits.max_joint_torque / largest;
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) tau[j] *= scale;
    }
  }
  // one factor for force and torque: the ratio of the two is where the palm is pushed
  double palm_scale = 1.0;
  const double palm_force = glm::length(result.palm_force);
  const double palm_torque = glm::length(result.palm_torque);
  if (palm_force > limits.max_palm_force) palm_scale = limits.max_palm_force / palm_force;
  if (palm_torque > limits.max_palm_torque)
    palm_scale = std::min(palm_scale, limits.max_palm_torque / palm_torque);
  result.palm_force *= palm_scale;
  result.palm_torque *= palm_scale;

  *out = result;
}

}  // namespace frusta
