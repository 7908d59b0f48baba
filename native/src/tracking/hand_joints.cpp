// SPDX-License-Identifier: MIT
#include "tracking/hand_joints.h"

#include <cassert>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

// XrHandJointEXT: palm, wrist, the thumb's four joints, then five per finger
constexpr int kXrPalm = 0;
constexpr int kXrWrist = 1;
constexpr int kXrThumbFirst = 2;  // metacarpal: the thumb's CMC, its chain's first point
constexpr int kXrFingerFirst = 6;  // the index finger's metacarpal
constexpr int kXrPerFinger = 5;
// keypoints: wrist, the thumb's four, then four per finger
constexpr int kKeypointWrist = 0;
constexpr int kKeypointThumbFirst = 1;
constexpr int kKeypointFingerFirst = 5;
constexpr int kKeypointPerFinger = 4;

constexpr int kFlagBits = FRUSTA_JOINT_ORIENTATION_VALID | FRUSTA_JOINT_POSITION_VALID |
                          FRUSTA_JOINT_ORIENTATION_TRACKED | FRUSTA_JOINT_POSITION_TRACKED;

const glm::dmat3 kMirror(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0);

// the XR index of a finger's metacarpal joint (fingers 1..4)
int xr_metacarpal(int finger) { return kXrFingerFirst + kXrPerFinger * (finger - 1); }

// OpenXR axes of a bone from the wrist towards `towards`, +Y as near the hand's +z as
// it can be. A def may put an MCP joint on the wrist or straight above it: then the
// hand's x stands in for the bone and its -x for the back.
glm::dmat3 bone_axes(const vec3& towards) {
  const double length = glm::length(towards);
  const vec3 along = length > 0.0 ? towards / length : vec3(1.0, 0.0, 0.0);
  const vec3 z(0.0, 0.0, 1.0);
  vec3 back = z - glm::dot(z, along) * along;
  if (glm::length(back) < 1e-9) back = vec3(-1.0, 0.0, 0.0) + along.x * along;
  back = glm::normalize(back);
  return xr_axes(glm::dmat3(along, glm::cross(back, along), back));
}

}  // namespace

bool is_joint_layout(int32_t layout) {
  return layout == FRUSTA_JOINT_LAYOUT_XR || layout == FRUSTA_JOINT_LAYOUT_KEYPOINTS;
}

int joint_count(int32_t layout) {
  assert(is_joint_layout(layout));
  return layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT;
}

int chain_joint(int32_t layout, int finger, int k) {
  assert(is_joint_layout(layout) && finger >= 0 && finger < FRUSTA_FINGER_COUNT && k >= 0 &&
         k < kChainPoints);
  if (layout == FRUSTA_JOINT_LAYOUT_XR)
    return finger == FRUSTA_FINGER_THUMB ? kXrThumbFirst + k : xr_metacarpal(finger) + 1 + k;
  return finger == FRUSTA_FINGER_THUMB
             ? kKeypointThumbFirst + k
             : kKeypointFingerFirst + kKeypointPerFinger * (finger - 1) + k;
}

int wrist_joint(int32_t layout) {
  return layout == FRUSTA_JOINT_LAYOUT_XR ? kXrWrist : kKeypointWrist;
}

glm::dmat3 xr_axes(const glm::dmat3& frame) { return glm::dmat3(-frame[1], frame[2], -frame[0]); }

PalmJoints palm_joints(const HandModel& model, int32_t layout) {
  const glm::dmat3 mirror = model.left ? kMirror : glm::dmat3(1.0);
  const double palm_radius = model.palm_spheres.empty() ? 0.0 : model.palm_spheres[0].radius;
  PalmJoints out;
  auto add = [&](int index, const vec3& position, double radius) -> PalmJoint& {
    PalmJoint& j = out.joints[static_cast<size_t>(out.count++)];
    j.index = index;
    j.position = position;
    j.radius = radius;
    return j;
  };
  const bool xr = layout == FRUSTA_JOINT_LAYOUT_XR;
  PalmJoint& wrist = add(wrist_joint(layout), vec3(0.0), palm_radius);
  wrist.has_orientation = xr;
  wrist.axes = xr_axes(glm::dmat3(1.0));
  // the thumb's chain starts at its CMC joint, which the palm carries
  add(chain_joint(layout, FRUSTA_FINGER_THUMB, 0),
      mirror * model.fingers[FRUSTA_FINGER_THUMB].base_position,
      model.fingers[FRUSTA_FINGER_THUMB].radius[0]);
  for (int f = FRUSTA_FINGER_INDEX; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerModel& finger = model.fingers[f];
    const vec3 mcp = mirror * finger.base_position;
    add(chain_joint(layout, f, 0), mcp, finger.radius[0]);
    if (!xr) continue;
    PalmJoint& metacarpal = add(xr_metacarpal(f), kCarpometacarpalFraction * mcp, finger.radius[0]);
    metacarpal.has_orientation = true;
    metacarpal.axes = bone_axes(mcp);
    if (f == FRUSTA_FINGER_MIDDLE) {
      PalmJoint& palm = add(kXrPalm, 0.5 * (metacarpal.position + mcp), palm_radius);
      palm.has_orientation = true;
      palm.axes = metacarpal.axes;
    }
  }
  assert(out.count == (xr ? kMaxPalmJoints : 6));
  return out;
}

frusta_result check_joint_layout(int32_t layout, const char* field) {
  if (is_joint_layout(layout)) return FRUSTA_OK;
  return fail(FRUSTA_ERROR_OUT_OF_RANGE,
              "%s is %d, must be FRUSTA_JOINT_LAYOUT_XR (0) or FRUSTA_JOINT_LAYOUT_KEYPOINTS (1)",
              field, layout);
}

frusta_result check_tracked_joint(const TrackedJoint& j, const char* name, int index) {
  if ((j.flags & ~kFlagBits) != 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "%s[%d].flags is 0x%x: bits beyond frusta_joint_flag's (0x%x) are set", name, index,
                static_cast<unsigned>(j.flags), static_cast<unsigned>(kFlagBits));
  if (j.flags & FRUSTA_JOINT_POSITION_VALID) {
    if (frusta_result r = check_bounded_named(glm::value_ptr(j.position), 3, kMaxCoordinate,
                                              "%s[%d].position", name, index))
      return r;
    if (frusta_result r =
            check_range_named(j.radius, 0.0, kMaxHandSize, false, "%s[%d].radius", name, index))
      return r;
  }
  if (j.flags & FRUSTA_JOINT_ORIENTATION_VALID) {
    if (frusta_result r =
            check_finite_named(glm::value_ptr(j.rotation), 4, "%s[%d].rotation", name, index))
      return r;
    const double norm = glm::length(j.rotation);
    if (!(norm >= kMinQuaternionNorm && norm <= kMaxQuaternionNorm))
      return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                  "%s[%d].rotation has norm %g; a unit quaternion (x, y, z, w) is expected "
                  "(norms in [%g, %g] are normalised)",
                  name, index, norm, kMinQuaternionNorm, kMaxQuaternionNorm);
  }
  return FRUSTA_OK;
}

frusta_result check_tracked_joints(const TrackedJoint* joints, int count, int32_t layout,
                                   const char* name) {
  if (frusta_result r = check_joint_layout(layout, "layout")) return r;
  if (count != joint_count(layout))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "count is %d, must be %d for layout %s", count,
                joint_count(layout),
                layout == FRUSTA_JOINT_LAYOUT_XR ? "FRUSTA_JOINT_LAYOUT_XR (FRUSTA_XR_JOINT_COUNT)"
                                                 : "FRUSTA_JOINT_LAYOUT_KEYPOINTS "
                                                   "(FRUSTA_KEYPOINT_COUNT)");
  for (int i = 0; i < count; ++i)
    if (frusta_result r = check_tracked_joint(joints[i], name, i)) return r;
  return FRUSTA_OK;
}

}  // namespace frusta
