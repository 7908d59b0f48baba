// SPDX-License-Identifier: MIT
#include "tracking/hand_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "tracking/rigid_fit.h"

namespace frusta {

namespace {

const glm::dmat3 kMirror(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0);
// metres: how much orientations weigh when they alone fix the palm's rotation (any
// weight would do; the points' spread, a few centimetres, keeps it well scaled)
constexpr double kFallbackOrientationWeight = 0.05;

}  // namespace

frusta_result check_hand_fit_options(const HandFitOptions& o) {
  if (frusta_result r = check_joint_layout(o.layout, "hand_fit_def.layout")) return r;
  if (o.max_iterations < 1 || o.max_iterations > kMaxFitIterations)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand_fit_def.max_iterations is %d, must be 1..%d",
                o.max_iterations, kMaxFitIterations);
  if (frusta_result r = check_range(o.orientation_weight, 0.0, kMaxOrientationWeight, false,
                                    "hand_fit_def.orientation_weight"))
    return r;
  if (frusta_result r = check_range(o.filter_min_cutoff, 0.0, kMaxFilterCutoff, false,
                                    "hand_fit_def.filter_min_cutoff"))
    return r;
  if (frusta_result r =
          check_range(o.filter_beta, 0.0, kMaxFilterBeta, false, "hand_fit_def.filter_beta"))
    return r;
  return check_range(o.filter_d_cutoff, kMinFilterDCutoff, kMaxFilterCutoff, false,
                     "hand_fit_def.filter_d_cutoff");
}

HandFitter::HandFitter(const HandModel& model, const HandFitOptions& options)
    : options_(options), left_(model.left), palm_(palm_joints(model, options.layout)) {
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerModel& finger = model.fingers[f];
    chains_[f] = finger_chain(finger);
    base_position_[f] = finger.base_position;
    base_rotation_[f] = finger.base_rotation;
    // before any fit: the rest pose, as a new hand has it
    for (int j = 0; j < 4; ++j) {
      angles_[f][j] = std::clamp(0.0, finger.joint_min[j], finger.joint_max[j]);
      angle_min_[static_cast<size_t>(f * 4 + j)] = finger.joint_min[j];
      angle_max_[static_cast<size_t>(f * 4 + j)] = finger.joint_max[j];
    }
  }
}

bool HandFitter::present(const TrackedJoint& j) const {
  return (j.flags & FRUSTA_JOINT_POSITION_VALID) &&
         (!options_.require_tracked || (j.flags & FRUSTA_JOINT_POSITION_TRACKED));
}

bool HandFitter::oriented(const TrackedJoint& j) const {
  return (j.flags & FRUSTA_JOINT_ORIENTATION_VALID) &&
         (!options_.require_tracked || (j.flags & FRUSTA_JOINT_ORIENTATION_TRACKED));
}

bool HandFitter::fit_palm(const TrackedJoint* joints, glm::dquat* rotation, vec3* position,
                          bool* from_orientation) const {
  RigidFit rigid;
  for (int i = 0; i < palm_.count; ++i) {
    const PalmJoint& p = palm_.joints[static_cast<size_t>(i)];
    if (present(joints[p.index])) rigid.add_point(p.position, joints[p.index].position, 1.0);
  }
  if (rigid.point_count() == 0) return false;
  *from_orientation = !rigid.points_fix_rotation();
  const double w = *from_orientation ? kFallbackOrientationWeight : options_.orientation_weight;
  // squared: a weight of 1e-300 m is none (its square is 0)
  const double weight = w * w;
  if (weight > 0.0) {
    for (int i = 0; i < palm_.count; ++i) {
      const PalmJoint& p = palm_.joints[static_cast<size_t>(i)];
      const TrackedJoint& j = joints[p.index];
      if (p.has_orientation && oriented(j))
        rigid.add_axes(p.axes, glm::mat3_cast(glm::normalize(j.rotation)), weight);
    }
  }
  if (*from_orientation && rigid.axes_count() == 0) return false;
  rigid.solve(rotation, position);
  return true;
}

double HandFitter::palm_residual(const TrackedJoint* joints, const glm::dquat& rotation,
                                 const vec3& position) const {
  const glm::dmat3 r = glm::mat3_cast(rotation);
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < palm_.count; ++i) {
    const PalmJoint& p = palm_.joints[static_cast<size_t>(i)];
    if (!present(joints[p.index])) continue;
    const vec3 d = position + r * p.position - joints[p.index].position;
    sum += glm::dot(d, d);
    ++n;
  }
  return n == 0 ? 0.0 : std::sqrt(sum / n);
}

FingerPoints HandFitter::finger_points(const TrackedJoint* joints, int f,
                                       const glm::dquat& rotation, const vec3& position) const {
  // joints frame -> hand frame -> the right hand's -> the finger's rest frame
  const glm::dmat3 to_rest = glm::transpose(base_rotation_[f]) *
                             (left_ ? kMirror : glm::dmat3(1.0)) *
                             glm::transpose(glm::mat3_cast(rotation));
  FingerPoints points;
  for (int k = 1; k < kChainPoints; ++k) {
    const TrackedJoint& j = joints[chain_joint(options_.layout, f, k)];
    points.present[static_cast<size_t>(k - 1)] = present(j);
    if (!present(j)) continue;
    points.point[static_cast<size_t>(k - 1)] =
        to_rest * (j.position - position) -
        glm::transpose(base_rotation_[f]) * base_position_[f];
  }
  return points;
}

void HandFitter::fit_local(const TrackedJoint* joints, HandFit* out) {
  glm::dquat rotation;
  vec3 position;
  bool from_orientation = false;
  const bool palm_fitted = fit_palm(joints, &rotation, &position, &from_orientation);
  out->palm_flags = 0;
  if (palm_fitted) {
    palm_rotation_ = rotation;
    palm_position_ = position;
    has_palm_ = true;
    if (from_orientation) out->palm_flags |= FRUSTA_FIT_ORIENTATION;
  } else {
    out->palm_flags |= FRUSTA_FIT_HELD | (has_palm_ ? 0 : FRUSTA_FIT_NO_HISTORY);
  }
  out->palm_residual = palm_residual(joints, palm_rotation_, palm_position_);

  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPoints points = finger_points(joints, f, palm_rotation_, palm_position_);
    FingerFitResult result;
    if (palm_fitted) {
      result = fit_finger(chains_[f], points, angles_[f], options_.max_iterations);
    } else {  // a finger on a held palm would follow a palm that is not there
      result.angles = angles_[f];
      result.flags = FRUSTA_FIT_HELD;
      result.residual = finger_residual(chains_[f], points, angles_[f]);
    }
    if (!(result.flags & FRUSTA_FIT_HELD)) has_finger_[f] = true;
    if (!has_finger_[f]) result.flags |= FRUSTA_FIT_NO_HISTORY;
    angles_[f] = result.angles;
    std::copy(result.angles.begin(), result.angles.end(),
              out->angles.begin() + f * FRUSTA_JOINTS_PER_FINGER);
    out->finger_residual[f] = result.residual;
    out->finger_flags[f] = result.flags;
  }

  out->palm_rotation = palm_rotation_;
  out->palm_position = palm_position_;
}

void HandFitter::fit(const TrackedJoint* joints, const vec3& frame_position,
                     const glm::dquat& frame_rotation, HandFit* out) {
  reset_filter();
  fit_local(joints, out);
  // the hand frame in the output frame
  out->palm_rotation = glm::normalize(frame_rotation * out->palm_rotation);
  out->palm_position = frame_position + glm::mat3_cast(frame_rotation) * out->palm_position;
}

frusta_result HandFitter::check_time(double time) const {
  if (!std::isfinite(time)) return fail(FRUSTA_ERROR_NOT_FINITE, "time is %g, must be finite", time);
  if (has_time_ && !(time > time_))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "time is %.17g s, must be after the previous sample's %.17g s", time, time_);
  return FRUSTA_OK;
}

void HandFitter::fit_at(double time, const TrackedJoint* joints, const vec3& frame_position,
                        const glm::dquat& frame_rotation, HandFit* out) {
  const double dt = has_time_ ? time - time_ : 0.0;
  has_time_ = true;
  time_ = time;
  fit_local(joints, out);
  // off costs one test: the fit is then fit()'s to the bit
  if (options_.filter_min_cutoff > 0.0) filter(dt, out);
  out->palm_rotation = glm::normalize(frame_rotation * out->palm_rotation);
  out->palm_position = frame_position + glm::mat3_cast(frame_rotation) * out->palm_position;
}

void HandFitter::reset_filter() {
  has_time_ = false;
  position_filter_.reset();
  rotation_filter_.reset();
  for (OneEuro<double>& a : angle_filter_) a.reset();
}

void HandFitter::filter(double dt, HandFit* out) {
  // tracking lost: what comes back is taken as it is, not dragged from a stale pose
  if (out->palm_flags & FRUSTA_FIT_HELD) {
    const double time = time_;
    reset_filter();
    has_time_ = true;
    time_ = time;
    return;
  }
  const OneEuroParams linear{options_.filter_min_cutoff, options_.filter_beta,
                             options_.filter_d_cutoff};
  const OneEuroParams angular{options_.filter_min_cutoff,
                              options_.filter_beta * kFilterAngularRadius,
                              options_.filter_d_cutoff};
  out->palm_position = position_filter_.filter(out->palm_position, dt, linear);
  out->palm_rotation = rotation_filter_.filter(out->palm_rotation, dt, angular);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const bool held = (out->finger_flags[f] & FRUSTA_FIT_HELD) != 0;
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      const size_t i = static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j);
      if (held) {
        angle_filter_[i].reset();
        continue;
      }
      // a mean of angles within the limits is within them, but for rounding
      out->angles[i] =
          std::clamp(angle_filter_[i].filter(out->angles[i], dt, angular), angle_min_[i], angle_max_[i]);
    }
  }
}

}  // namespace frusta
