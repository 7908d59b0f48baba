// SPDX-License-Identifier: MIT
// C ABI: tracked hands. Fitters behind frusta_hand_fitter_id, joints from a posed hand,
// and a hand def calibrated from tracked joints. Each call checks every input first.
#include <array>
#include <memory>

#include "capi/convert.h"
#include "capi/registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"
#include "hand/kinematics.h"
#include "tracking/hand_calibration.h"
#include "tracking/hand_fit.h"
#include "tracking/joints_from_hand.h"

using namespace frusta;

namespace {

using FitterRegistry = Registry<HandFitter, frusta_hand_fitter_id>;

FitterRegistry& fitter_registry() {
  static FitterRegistry registry("hand fitter");
  return registry;
}

// A hand def from the caller, checked whole.
frusta_result read_checked_hand_def(const frusta_hand_def* def, HandDef* out) {
  if (frusta_result r = check_def_input(def, "frusta_hand_def")) return r;
  *out = read_hand_def(*def);
  return check_hand_def(*out);
}

frusta_result read_fit_def(const frusta_hand_fit_def* def, HandFitOptions* out) {
  if (frusta_result r = check_pointer(def, "fit_def")) return r;
  if (frusta_result r = check_def_input(def, "frusta_hand_fit_def")) return r;
  if (def->require_tracked != 0 && def->require_tracked != 1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand_fit_def.require_tracked is %d, must be 0 or 1",
                def->require_tracked);
  HandFitOptions o;
  o.layout = def->layout;
  o.require_tracked = def->require_tracked == 1;
  o.max_iterations = def->max_iterations;
  o.orientation_weight = def->orientation_weight;
  o.filter_min_cutoff = def->filter_min_cutoff;
  o.filter_beta = def->filter_beta;
  o.filter_d_cutoff = def->filter_d_cutoff;
  if (frusta_result r = check_hand_fit_options(o)) return r;
  *out = o;
  return FRUSTA_OK;
}

}  // namespace

FRUSTA_API frusta_hand_fit_def frusta_default_hand_fit_def(void) {
  frusta_hand_fit_def def = blank_def<frusta_hand_fit_def>();
  const HandFitOptions o;
  def.layout = o.layout;
  def.require_tracked = o.require_tracked ? 1 : 0;
  def.max_iterations = o.max_iterations;
  def.orientation_weight = o.orientation_weight;
  def.filter_min_cutoff = o.filter_min_cutoff;
  def.filter_beta = o.filter_beta;
  def.filter_d_cutoff = o.filter_d_cutoff;
  return def;
}

FRUSTA_API frusta_result frusta_create_hand_fitter(const frusta_hand_def* def,
                                                   const frusta_hand_fit_def* fit_def,
                                                   frusta_hand_fitter_id* out_fitter) {
  HandDef hand;
  if (frusta_result r = read_checked_hand_def(def, &hand)) return r;
  HandFitOptions options;
  if (frusta_result r = read_fit_def(fit_def, &options)) return r;
  if (frusta_result r = check_pointer(out_fitter, "out_fitter")) return r;
  return guarded("frusta_create_hand_fitter", [&] {
    return fitter_registry().add(std::make_unique<HandFitter>(make_hand_model(hand), options),
                                 out_fitter);
  });
}

FRUSTA_API frusta_result frusta_destroy_hand_fitter(frusta_hand_fitter_id fitter) {
  return fitter_registry().destroy(fitter);
}

FRUSTA_API int32_t frusta_hand_fitter_is_valid(frusta_hand_fitter_id fitter) {
  return fitter_registry().is_valid(fitter) ? 1 : 0;
}

namespace {

// frusta_hand_fitter_fit(_at): every input checked, then one fit; timed when time is
frusta_result fit_sample(frusta_hand_fitter_id fitter, const double* time,
                         const frusta_tracked_joint* joints, int32_t count,
                         const frusta_pose* frame, frusta_hand_fit* out) {
  HandFitter* f = nullptr;
  if (frusta_result r = fitter_registry().find(fitter, &f)) return r;
  if (time)
    if (frusta_result r = f->check_time(*time)) return r;
  if (frusta_result r = check_pointer(joints, "joints")) return r;
  Pose frame_pose;
  if (frame)
    if (frusta_result r = read_pose(frame, "frame", &frame_pose)) return r;
  if (frusta_result r = check_out_struct(out, "out", "frusta_hand_fit")) return r;
  // no more than a layout's joints are read; a wrong count is refused before any is
  std::array<TrackedJoint, kMaxTrackedJoints> in;
  for (int32_t i = 0; i < count && i < kMaxTrackedJoints; ++i) in[static_cast<size_t>(i)] = read_tracked_joint(joints[i]);
  if (frusta_result r = check_tracked_joints(in.data(), count, f->options().layout, "joints"))
    return r;

  HandFit fit;
  if (time)
    f->fit_at(*time, in.data(), frame_pose.position, frame_pose.rotation, &fit);
  else
    f->fit(in.data(), frame_pose.position, frame_pose.rotation, &fit);
  out->palm_flags = fit.palm_flags;
  store(Pose{fit.palm_position, fit.palm_rotation}, &out->palm);
  std::copy(fit.angles.begin(), fit.angles.end(), out->angles);
  out->palm_residual = fit.palm_residual;
  std::copy(fit.finger_residual.begin(), fit.finger_residual.end(), out->finger_residual);
  std::copy(fit.finger_flags.begin(), fit.finger_flags.end(), out->finger_flags);
  out->reserved0 = 0;
  return FRUSTA_OK;
}

}  // namespace

FRUSTA_API frusta_result frusta_hand_fitter_fit(frusta_hand_fitter_id fitter,
                                                const frusta_tracked_joint* joints,
                                                int32_t count, const frusta_pose* frame,
                                                frusta_hand_fit* out) {
  return fit_sample(fitter, nullptr, joints, count, frame, out);
}

FRUSTA_API frusta_result frusta_hand_fitter_fit_at(frusta_hand_fitter_id fitter, double time,
                                                   const frusta_tracked_joint* joints,
                                                   int32_t count, const frusta_pose* frame,
                                                   frusta_hand_fit* out) {
  return fit_sample(fitter, &time, joints, count, frame, out);
}

FRUSTA_API frusta_result frusta_hand_joints_from_pose(const frusta_hand_def* def, int32_t layout,
                                                      const frusta_pose* palm,
                                                      const double* angles, int32_t angle_count,
                                                      frusta_tracked_joint* out, int32_t capacity,
                                                      int32_t* out_count) {
  HandDef hand;
  if (frusta_result r = read_checked_hand_def(def, &hand)) return r;
  if (frusta_result r = check_joint_layout(layout, "layout")) return r;
  Pose p;
  if (frusta_result r = read_pose(palm, "palm", &p)) return r;
  HandState state;
  if (frusta_result r = read_joint_angles(angles, angle_count, "angles", &state.angles)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  return guarded("frusta_hand_joints_from_pose", [&] {
    const HandModel model = make_hand_model(hand);
    state.palm_position = p.position;
    state.palm_rotation = p.rotation;
    clamp_to_limits(model, state);
    HandPose pose;
    forward_kinematics(model, state, pose);
    std::array<TrackedJoint, kMaxTrackedJoints> joints;
    joints_from_hand(model, pose, layout, joints.data());
    return fill_output_array(capacity, joint_count(layout), out_count,
                             [&](int32_t i) { store(joints[static_cast<size_t>(i)], &out[i]); });
  });
}

FRUSTA_API frusta_result frusta_calibrate_hand_def(const frusta_tracked_joint* frames,
                                                   int32_t frame_count, int32_t layout,
                                                   frusta_hand_def* def) {
  HandDef hand;
  if (frusta_result r = read_checked_hand_def(def, &hand)) return r;
  if (frusta_result r = check_joint_layout(layout, "layout")) return r;
  if (frame_count < 1 || frame_count > kMaxCalibrationFrames)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "frame_count is %d, must be 1..%d", frame_count,
                kMaxCalibrationFrames);
  if (frusta_result r = check_pointer(frames, "frames")) return r;
  return guarded("frusta_calibrate_hand_def", [&] {
    // frame by frame: only the distances between joints are kept
    const int count = joint_count(layout);
    HandCalibration calibration(layout, frame_count);
    std::array<TrackedJoint, kMaxTrackedJoints> joints;
    for (int32_t i = 0; i < frame_count; ++i) {
      for (int j = 0; j < count; ++j) {
        const int32_t index = i * count + j;
        joints[static_cast<size_t>(j)] = read_tracked_joint(frames[index]);
        if (frusta_result r = check_tracked_joint(joints[static_cast<size_t>(j)], "frames", index))
          return r;
      }
      calibration.add_frame(joints.data());
    }
    if (frusta_result r = calibration.size(&hand)) return r;
    store_hand_def(hand, def);
    return FRUSTA_OK;
  });
}
