// SPDX-License-Identifier: MIT
#include "capi/convert.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

frusta_result check_point(const double point[3], const std::string& field) {
  return check_bounded(point, 3, kMaxCoordinate, field.c_str());
}

frusta_result check_radius(double radius, const std::string& field) {
  return check_range(radius, 0.0, kMaxCoordinate, false, field.c_str());
}

vec3 to_vec3(const double v[3]) { return vec3(v[0], v[1], v[2]); }

// the header's (x, y, z, w) order; GLM's constructor takes w first
glm::dquat to_quat(const double q[4]) { return glm::dquat(q[3], q[0], q[1], q[2]); }

void store(const glm::dquat& q, double out[4]) {
  out[0] = q.x;
  out[1] = q.y;
  out[2] = q.z;
  out[3] = q.w;
}

}  // namespace

frusta_result check_output_array(const void* out, const char* out_name, int32_t capacity,
                                 const int32_t* out_count) {
  if (frusta_result r = check_pointer(out_count, "out_count")) return r;
  // a wrong argument, not a small buffer
  if (capacity < 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "capacity is %d, must be >= 0", capacity);
  if (capacity > 0 && out == nullptr)
    return fail(FRUSTA_ERROR_NULL_POINTER, "%s is null but capacity is %d (null only with 0)",
                out_name, capacity);
  return FRUSTA_OK;
}

frusta_result read_segment(const frusta_segment* in, const char* name, Segment* out) {
  const std::string n = name;
  if (frusta_result r = check_pointer(in, name)) return r;
  if (frusta_result r = check_point(in->proximal, n + ".proximal")) return r;
  if (frusta_result r = check_point(in->distal, n + ".distal")) return r;
  if (frusta_result r = check_radius(in->proximal_radius, n + ".proximal_radius")) return r;
  if (frusta_result r = check_radius(in->distal_radius, n + ".distal_radius")) return r;
  *out = {to_vec3(in->proximal), to_vec3(in->distal), in->proximal_radius, in->distal_radius};
  return FRUSTA_OK;
}

frusta_result read_sphere(const frusta_sphere* in, const char* name, Sphere* out) {
  const std::string n = name;
  if (frusta_result r = check_pointer(in, name)) return r;
  if (frusta_result r = check_point(in->center, n + ".center")) return r;
  if (frusta_result r = check_radius(in->radius, n + ".radius")) return r;
  *out = {to_vec3(in->center), in->radius};
  return FRUSTA_OK;
}

frusta_result read_pose(const frusta_pose* in, const char* name, Pose* out) {
  const std::string n = name;
  if (frusta_result r = check_pointer(in, name)) return r;
  if (frusta_result r = check_point(in->position, n + ".position")) return r;
  if (frusta_result r = check_finite(in->rotation, 4, (n + ".rotation").c_str())) return r;
  const glm::dquat q = to_quat(in->rotation);
  const double norm = glm::length(q);
  if (!(norm >= kMinQuaternionNorm && norm <= kMaxQuaternionNorm))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s.rotation has norm %g; a unit quaternion (x, y, z, "
                "w) is expected (norms in [0.5, 2] are normalised)", name, norm);
  *out = {to_vec3(in->position), q / norm};
  return FRUSTA_OK;
}

frusta_result read_joint_angles(const double* in, int32_t count, const char* name,
                                std::array<double, FRUSTA_HAND_JOINT_COUNT>* out) {
  if (frusta_result r = check_pointer(in, name)) return r;
  if (count != FRUSTA_HAND_JOINT_COUNT)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "count is %d, must be FRUSTA_HAND_JOINT_COUNT (%d)",
                count, FRUSTA_HAND_JOINT_COUNT);
  if (frusta_result r = check_bounded(in, count, kMaxJointAngle, name)) return r;
  std::copy(in, in + FRUSTA_HAND_JOINT_COUNT, out->begin());
  return FRUSTA_OK;
}

namespace {

// the fields both defs share, by name, from one to the other
template <class From, class To>
void copy_hand_fields(const From& in, To& out) {
  out.side = in.side;
  out.hand_length = in.hand_length;
  out.hand_breadth = in.hand_breadth;
  std::memcpy(out.segment_length, in.segment_length, sizeof out.segment_length);
  std::memcpy(out.joint_radius, in.joint_radius, sizeof out.joint_radius);
  std::memcpy(out.base_position, in.base_position, sizeof out.base_position);
  std::memcpy(out.base_rotation, in.base_rotation, sizeof out.base_rotation);
  std::memcpy(out.joint_min, in.joint_min, sizeof out.joint_min);
  std::memcpy(out.joint_max, in.joint_max, sizeof out.joint_max);
  out.palm_length = in.palm_length;
  out.palm_breadth = in.palm_breadth;
  out.palm_thickness = in.palm_thickness;
}

static_assert(sizeof(HandDef::joint_radius) == sizeof(frusta_hand_def::joint_radius) &&
                  sizeof(HandDef::base_position) == sizeof(frusta_hand_def::base_position),
              "the two hand defs hold the same arrays");

}  // namespace

HandDef read_hand_def(const frusta_hand_def& in) {
  HandDef out;
  copy_hand_fields(in, out);
  return out;
}

void store_hand_def(const HandDef& in, frusta_hand_def* out) { copy_hand_fields(in, *out); }

TrackedJoint read_tracked_joint(const frusta_tracked_joint& in) {
  TrackedJoint out;
  out.position = to_vec3(in.position);
  out.rotation = to_quat(in.rotation);
  out.radius = in.radius;
  out.flags = in.flags;
  return out;
}

void store(const TrackedJoint& in, frusta_tracked_joint* out) {
  store(in.position, out->position);
  store(in.rotation, out->rotation);
  out->radius = in.radius;
  out->flags = in.flags;
  out->reserved0 = 0;
}

void store(const vec3& v, double out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = v[k];
}

void store(const Pose& pose, frusta_pose* out) {
  store(pose.position, out->position);
  store(pose.rotation, out->rotation);
}

Pose to_pose(const vec3& position, const glm::dmat3& rotation) {
  return {position, glm::normalize(glm::quat_cast(rotation))};
}

frusta_result copy_segments(const HandModel& model, const HandPose& pose, frusta_segment* out,
                            int32_t capacity, int32_t* out_count) {
  return fill_output_array(capacity, FRUSTA_HAND_SEGMENT_COUNT, out_count, [&](int32_t i) {
    const Segment seg = finger_segment(model, pose, i / FRUSTA_SEGMENTS_PER_FINGER,
                                       i % FRUSTA_SEGMENTS_PER_FINGER);
    frusta_segment& o = out[i];
    store(seg.proximal, o.proximal);
    store(seg.distal, o.distal);
    o.proximal_radius = seg.proximal_radius;
    o.distal_radius = seg.distal_radius;
  });
}

frusta_result copy_palm_spheres(const HandModel& model, const HandPose& pose, frusta_sphere* out,
                                int32_t capacity, int32_t* out_count) {
  const int32_t count = static_cast<int32_t>(model.palm_spheres.size());
  return fill_output_array(capacity, count, out_count, [&](int32_t i) {
    const Sphere s = palm_sphere(model, pose, i);
    store(s.center, out[i].center);
    out[i].radius = s.radius;
  });
}

}  // namespace frusta
