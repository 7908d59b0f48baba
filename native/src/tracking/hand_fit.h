// SPDX-License-Identifier: MIT
// Tracked joints to a Frusta hand: the palm pose (a rigid fit of the palm-rigid joints)
// and the 20 joint angles (each finger fit to its moving joints), with residuals and
// flags, keeping the last good value of whatever too few joints determine. The fitter
// holds that history; a fit allocates nothing.
#pragma once

#include <array>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>

#include "hand/hand_model.h"
#include "tracking/finger_fit.h"
#include "tracking/hand_joints.h"
#include "tracking/one_euro.h"

namespace frusta {

// frusta_hand_fit_def's fields; ranges there.
struct HandFitOptions {
  int32_t layout = FRUSTA_JOINT_LAYOUT_XR;  // frusta_joint_layout
  bool require_tracked = false;  // a valid joint counts only when tracked too
  int32_t max_iterations = 10;   // refining steps per finger
  double orientation_weight = 0.0;  // metres; 0: orientations only when points fall short
  // the One Euro filter of timed fits; defaults measured (README, tracked hands)
  double filter_min_cutoff = 1.0;  // Hz; 0: off
  double filter_beta = 2.0;        // 1/m: Hz per m/s
  double filter_d_cutoff = 1.0;    // Hz
};

constexpr int32_t kMaxFitIterations = 100;
constexpr double kMaxOrientationWeight = 1.0;  // metres
constexpr double kMaxFilterCutoff = 1000.0;    // Hz, min_cutoff and d_cutoff
constexpr double kMaxFilterBeta = 1000.0;      // 1/m
constexpr double kMinFilterDCutoff = 1e-3;     // Hz
// metres: a rotation's or an angle's rad/s count as a point's speed this far from the axis
constexpr double kFilterAngularRadius = 0.1;

// The one check of a fit def's fields; the thread's error names the field.
frusta_result check_hand_fit_options(const HandFitOptions& options);

// frusta_hand_fit's fields: the hand frame in the output frame, the angles, how good.
struct HandFit {
  vec3 palm_position{0.0};
  glm::dquat palm_rotation{1.0, 0.0, 0.0, 0.0};
  std::array<double, FRUSTA_HAND_JOINT_COUNT> angles{};  // radians, within the limits
  double palm_residual = 0.0;                             // metres, RMS
  std::array<double, FRUSTA_FINGER_COUNT> finger_residual{};  // metres, RMS
  int32_t palm_flags = 0;                                 // frusta_fit_flag bits
  std::array<int32_t, FRUSTA_FINGER_COUNT> finger_flags{};
};

class HandFitter {
 public:
  // model: a checked hand's; options: checked by check_hand_fit_options.
  HandFitter(const HandModel& model, const HandFitOptions& options);

  // Fit joint_count(layout) joints that passed check_tracked_joints, given in a frame
  // whose pose in the output frame is (frame_position, frame_rotation, unit).
  // Unfiltered; restarts the filter.
  void fit(const TrackedJoint* joints, const vec3& frame_position,
           const glm::dquat& frame_rotation, HandFit* out);
  // The one check of a sample's time: finite, after the previous timed sample's.
  frusta_result check_time(double time) const;
  // fit of a sample at time (passed check_time), through the One Euro filter
  void fit_at(double time, const TrackedJoint* joints, const vec3& frame_position,
              const glm::dquat& frame_rotation, HandFit* out);

  const HandFitOptions& options() const { return options_; }

 private:
  // the fit in the joints' frame (the palm in out before composing it with a frame)
  void fit_local(const TrackedJoint* joints, HandFit* out);
  void filter(double dt, HandFit* out);
  void reset_filter();
  bool present(const TrackedJoint& joint) const;
  bool oriented(const TrackedJoint& joint) const;
  // the palm in the joints' frame; false when the joints do not fix it
  bool fit_palm(const TrackedJoint* joints, glm::dquat* rotation, vec3* position,
                bool* from_orientation) const;
  double palm_residual(const TrackedJoint* joints, const glm::dquat& rotation,
                       const vec3& position) const;
  // finger f's moving joints in its rest frame, for the palm at (rotation, position)
  FingerPoints finger_points(const TrackedJoint* joints, int f, const glm::dquat& rotation,
                             const vec3& position) const;

  HandFitOptions options_;
  bool left_ = false;
  PalmJoints palm_;
  std::array<FingerChain, FRUSTA_FINGER_COUNT> chains_{};
  std::array<vec3, FRUSTA_FINGER_COUNT> base_position_{};        // right hand's
  std::array<glm::dmat3, FRUSTA_FINGER_COUNT> base_rotation_{};  // right hand's
  // the last good fit, in the joints' frame
  bool has_palm_ = false;
  vec3 palm_position_{0.0};
  glm::dquat palm_rotation_{1.0, 0.0, 0.0, 0.0};
  std::array<std::array<double, 4>, FRUSTA_FINGER_COUNT> angles_{};
  std::array<bool, FRUSTA_FINGER_COUNT> has_finger_{};
  // the filter: the last timed sample's time, and each output's state
  std::array<double, FRUSTA_HAND_JOINT_COUNT> angle_min_{}, angle_max_{};
  bool has_time_ = false;
  double time_ = 0.0;
  OneEuro<vec3> position_filter_;
  OneEuroRotation rotation_filter_;
  std::array<OneEuro<double>, FRUSTA_HAND_JOINT_COUNT> angle_filter_{};
};

}  // namespace frusta
