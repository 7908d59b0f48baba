// SPDX-License-Identifier: MIT
// The palm's 6-DOF solve (seed [0156]), run before the fingers: the palm moves as a
// rigid body carrying the fingers at their graphic angles, so the fingers then start
// their own solve from a hand that touches nothing.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "solver/detection.h"
#include "solver/qp.h"
#include "solver/solver_params.h"
#include "solver/stage.h"

namespace frusta {

// A palm placement and how far a move between two of them can carry any hand point.
struct PalmPlacement {
  vec3 position{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
};
double palm_motion(const HandReach& reach, const PalmPlacement& from, const PalmPlacement& to);
// The rotation vector taking `from` to `to` (world frame), the short way round.
vec3 rotation_between(const glm::dquat& from, const glm::dquat& to);

// The way the haptic palm moved this step (unit, or 0 where it did not): the graphic palm
// goes no further back against it than `slack` (metres) from where it was, `from`. A
// palm trailing the haptic one then closes the gap, and with it the force (seed eq. 12),
// no faster than the haptic palm moves, even where the haptic hand turns back.
struct PalmHeading {
  vec3 from{0.0};
  vec3 way{0.0};
  double slack = 0.0;
};

// A hand that starts a sub-step deeper than this many penetration tolerances (an object
// moved into it) is lifted out by the palm, fingers and all.
constexpr double kRecoveryTolerances = 10.0;

class PalmStage : public StageEstimate {
 public:
  // motion_cap: how far (m) any point may move from where the stage starts; heading: the
  // way it may not go back; slide: step within its bound's faces (the hand held back by its
  // continuity budget); poses: where it poses its trials (StagePoses); start_gap:
  // clearance(pose), which the caller has measured
  PalmStage(const StageInputs& inputs, const PalmPlacement& target, double motion_cap,
            const PalmHeading& heading, bool slide, QpHints& hints, StagePoses& poses,
            HandState& state, HandPose& pose, double start_gap);

  int dofs() const { return 6; }
  double objective() const;
  int32_t row_capacity() const {
    return inputs_.candidates.size() + 1;
  }
  int32_t linearise(QpRow* rows, double* target, double* weights, double radius) const;
  double step_motion(const double* d) const;
  double try_step(const double* d, double s);
  // (try_step itself checks every candidate)
  double try_step_anywhere(const double* d) { return try_step(d, 1.0); }
  double try_between(double s);
  int32_t lazy_rows(const double* d, QpRow* rows) const;

  // The smallest exact gap between the whole hand and every candidate.
  double clearance(const HandPose& pose) const;

 private:
  double trial_clearance();  // of the trial state, posed
  const StageInputs inputs_;
  PalmPlacement target_;
  PalmPlacement start_;
  double motion_cap_;
  PalmHeading heading_;
  bool slide_;
  bool recovering_ = false;  // started deep: finger rows push out too
};

}  // namespace frusta
