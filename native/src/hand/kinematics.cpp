// SPDX-License-Identifier: MIT
#include "hand/kinematics.h"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

glm::dmat3 rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dmat3(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);  // column-major
}

// positive flexion turns +x towards -z, the palm side
glm::dmat3 rotation_y(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dmat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
}

const glm::dmat3 kMirror(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0);

}  // namespace

frusta_result check_hand_state(const HandState& state, const char* name) {
  const double* position = glm::value_ptr(state.palm_position);
  const double* rotation = glm::value_ptr(state.palm_rotation);
  const double* angles = state.angles.data();
  const double norm = glm::length(state.palm_rotation);
  // one pass without formatting: gloves call this for every sample
  if (all_bounded(position, 3, kMaxCoordinate) && all_finite(rotation, 4) &&
      norm >= kMinQuaternionNorm && norm <= kMaxQuaternionNorm &&
      all_bounded(angles, FRUSTA_HAND_JOINT_COUNT, kMaxJointAngle))
    return FRUSTA_OK;
  if (frusta_result r = check_bounded_named(position, 3, kMaxCoordinate, "%s.palm_position", name))
    return r;
  if (frusta_result r = check_finite_named(rotation, 4, "%s.palm_rotation", name)) return r;
  if (!(norm >= kMinQuaternionNorm && norm <= kMaxQuaternionNorm))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "%s.palm_rotation has norm %g; a unit quaternion is expected (norms in [%g, %g] "
                "are normalised)", name, norm, kMinQuaternionNorm, kMaxQuaternionNorm);
  return check_bounded_named(angles, FRUSTA_HAND_JOINT_COUNT, kMaxJointAngle, "%s.angles", name);
}

HandState interpolate(const HandState& a, const HandState& b, double t) {
  HandState s;
  s.palm_position = a.palm_position + t * (b.palm_position - a.palm_position);
  s.palm_rotation = glm::slerp(a.palm_rotation, b.palm_rotation, t);
  for (size_t j = 0; j < s.angles.size(); ++j) s.angles[j] = a.angles[j] + t * (b.angles[j] - a.angles[j]);
  return s;
}

void clamp_to_limits(const HandModel& model, HandState& state) {
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerModel& finger = model.fingers[f];
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      double& a = state.angles[f * FRUSTA_JOINTS_PER_FINGER + j];
      a = std::clamp(a, finger.joint_min[j], finger.joint_max[j]);
    }
  }
}

void finger_kinematics(const HandModel& model, const HandState& state, int f, HandPose& pose) {
  // a left hand is built as a right hand and reflected through the hand's x-z plane;
  // the reflection turns axes (pseudo-vectors) the other way, and keeps segment
  // frames right-handed by flipping their y
  const glm::dmat3 to_world = model.left ? pose.palm_rotation * kMirror : pose.palm_rotation;
  const double axis_sign = model.left ? -1.0 : 1.0;

  const FingerModel& finger = model.fingers[f];
  const double* q = &state.angles[f * FRUSTA_JOINTS_PER_FINGER];
  FingerPose& out = pose.fingers[f];

  const glm::dmat3 rest = finger.base_rotation * rotation_z(q[0]);
  out.abduction_axis = axis_sign * (to_world * finger.base_rotation[2]);
  out.flexion_axis = axis_sign * (to_world * rest[1]);

  vec3 joint = finger.base_position;
  out.joint[0] = pose.palm_position + to_world * joint;
  double flexion = 0.0;
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
    flexion += q[1 + s];
    const glm::dmat3 local = rest * rotation_y(flexion);
    // a right hand's frames need no fix (every trial of a stage paid a product with the
    // identity per segment: 0.4 % of the 10^4-leaf grasp's instructions)
    out.segment_rotation[s] = model.left ? to_world * local * kMirror : to_world * local;
    joint += finger.length[s] * local[0];
    out.joint[s + 1] = pose.palm_position + to_world * joint;
  }
}

void forward_kinematics(const HandModel& model, const HandState& state, HandPose& pose) {
  pose.palm_position = state.palm_position;
  pose.palm_rotation = glm::mat3_cast(state.palm_rotation);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) finger_kinematics(model, state, f, pose);
}

Segment finger_segment(const HandModel& model, const HandPose& pose, int finger, int segment) {
  const FingerModel& m = model.fingers[finger];
  const FingerPose& p = pose.fingers[finger];
  return {p.joint[segment], p.joint[segment + 1], m.radius[segment], m.radius[segment + 1]};
}

Sphere palm_sphere(const HandModel& model, const HandPose& pose, int index) {
  const Sphere& local = model.palm_spheres[static_cast<size_t>(index)];
  return {pose.palm_position + pose.palm_rotation * local.center, local.radius};
}

vec3 segment_point(const HandPose& pose, int finger, int segment, const vec3& local) {
  const FingerPose& p = pose.fingers[finger];
  return p.joint[segment] + p.segment_rotation[segment] * local;
}

void point_jacobian(const HandPose& pose, int finger, int segment, const vec3& world_point,
                    double jacobian[3 * kJacobianColumns]) {
  const FingerPose& p = pose.fingers[finger];
  vec3 columns[kJacobianColumns];
  columns[0] = glm::cross(p.abduction_axis, world_point - p.joint[0]);
  // flexion joint j (1..3) sits at joint[j - 1] and moves segments j - 1 and beyond
  for (int j = 1; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    columns[j] = j - 1 <= segment ? glm::cross(p.flexion_axis, world_point - p.joint[j - 1])
                                  : vec3(0.0);
  const vec3 arm = world_point - pose.palm_position;
  for (int k = 0; k < 3; ++k) {
    vec3 e(0.0);
    e[k] = 1.0;
    columns[FRUSTA_JOINTS_PER_FINGER + k] = e;
    columns[FRUSTA_JOINTS_PER_FINGER + 3 + k] = glm::cross(e, arm);
  }
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < kJacobianColumns; ++col)
      jacobian[row * kJacobianColumns + col] = columns[col][row];
}

}  // namespace frusta
