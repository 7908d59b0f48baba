// SPDX-License-Identifier: MIT
// Checked conversions from the C ABI's structs to the engine's types. Each names
// the offending field in the thread's error and leaves *out untouched on failure.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <glm/gtc/quaternion.hpp>

#include "core/validate.h"
#include "frusta/frusta.h"
#include "geometry/types.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "tracking/hand_joints.h"

namespace frusta {

struct Pose {
  vec3 position{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // normalised
};

// What every frusta_default_*_def() starts from: zeroed (padding and reserved fields
// too), this library's size, and the cookie check_def_input looks for.
template <class Def>
Def blank_def() {
  Def def;
  std::memset(&def, 0, sizeof def);
  def.struct_size = sizeof(Def);
  def.internal_value = kDefCookie;
  return def;
}

// A def from the caller: not null, this library's size, made by its frusta_default_*_def().
template <class Def>
frusta_result check_def_input(const Def* def, const char* struct_name) {
  if (frusta_result r = check_pointer(def, "def")) return r;
  if (frusta_result r = check_struct_size(def->struct_size, sizeof(Def), struct_name)) return r;
  return check_def_cookie(def->internal_value, struct_name);
}

// A single out-struct from the caller: not null, and the struct_size it set before the
// call this library's size.
template <class Out>
frusta_result check_out_struct(const Out* out, const char* name, const char* struct_name) {
  if (frusta_result r = check_pointer(out, name)) return r;
  return check_struct_size(out->struct_size, sizeof(Out), struct_name);
}

// The header's output-array rule, checked before anything is written: out_count not
// null, capacity >= 0, out null only with capacity 0. The caller then sets *out_count
// to the count and writes min(capacity, count) elements.
frusta_result check_output_array(const void* out, const char* out_name, int32_t capacity,
                                 const int32_t* out_count);

// The rest of that rule, once check_output_array passed: write(i) for each of the first
// min(capacity, count) elements, then *out_count = count.
template <class Write>
frusta_result fill_output_array(int32_t capacity, int32_t count, int32_t* out_count, Write write) {
  const int32_t n = std::min(capacity, count);
  for (int32_t i = 0; i < n; ++i) write(i);
  *out_count = count;
  return FRUSTA_OK;
}

// A hand's geometry at `pose` by the rest of the output-array rule (check_output_array
// passed): every finger segment, finger-major, proximal to distal; every palm sphere.
// The one conversion for standalone hands and a world's.
frusta_result copy_segments(const HandModel& model, const HandPose& pose, frusta_segment* out,
                            int32_t capacity, int32_t* out_count);
frusta_result copy_palm_spheres(const HandModel& model, const HandPose& pose, frusta_sphere* out,
                                int32_t capacity, int32_t* out_count);

// name prefixes the field names in messages, e.g. "segment" -> "segment.distal[1]"
frusta_result read_segment(const frusta_segment* in, const char* name, Segment* out);
frusta_result read_sphere(const frusta_sphere* in, const char* name, Sphere* out);
// Positions within kMaxCoordinate; a quaternion whose norm lies within
// [kMinQuaternionNorm, kMaxQuaternionNorm] is normalised.
frusta_result read_pose(const frusta_pose* in, const char* name, Pose* out);

// FRUSTA_HAND_JOINT_COUNT finite angles within kMaxJointAngle; count must equal it.
frusta_result read_joint_angles(const double* in, int32_t count, const char* name,
                                std::array<double, FRUSTA_HAND_JOINT_COUNT>* out);

// The def's fields as they are (check_hand_def checks them), both ways; store_hand_def
// leaves out's struct_size and internal_value as they were.
HandDef read_hand_def(const frusta_hand_def& in);
void store_hand_def(const HandDef& in, frusta_hand_def* out);

// A tracked joint's fields as they are (check_tracked_joint checks them), both ways.
TrackedJoint read_tracked_joint(const frusta_tracked_joint& in);
void store(const TrackedJoint& in, frusta_tracked_joint* out);

void store(const vec3& v, double out[3]);
void store(const Pose& pose, frusta_pose* out);
Pose to_pose(const vec3& position, const glm::dmat3& rotation);

}  // namespace frusta
