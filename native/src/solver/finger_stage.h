// SPDX-License-Identifier: MIT
// One finger's solve on a fixed palm (seed eq. 6 over the finger's joints, eq. 9 and the
// endpoint rule per candidate, joint limits as rows). Abduction is solved too: a
// sideways haptic abduction can push a finger into an object as well as a flexion can.
#pragma once

#include <array>

#include "solver/detection.h"
#include "solver/finger_motion.h"
#include "solver/qp.h"
#include "solver/solver_params.h"
#include "solver/stage.h"

namespace frusta {

// The smallest exact gap (0 when apart) between a finger at `pose` and its candidates.
double finger_clearance(const HandModel& model, const HandPose& pose,
                        const CandidateSet& candidates, int finger);

// How a finger stage keeps within its motion cap.
enum class FingerBound {
  kHalve,  // steps towards its target, halved until within the cap
  // steps within rows that bound the move to the cap: the best step the cap allows. For
  // a target further than the cap: a step towards it cut short follows rows linearised
  // for where it is aimed (the far target projected onto them), sliding sideways
  // instead of closing a gap to the surface near: a press from open took 38 sub-steps
  // and touched the box only in its fifth
  kTrust,
  kSlide,  // within rows taking half the cap's rest each: the hand held back by its budget
};

class FingerStage : public StageEstimate {
 public:
  // state/pose: the graphic hand, updated in place; target: this stage's goal angles;
  // cap: how far (m) any point may move from where the stage starts; poses: where it
  // poses its trials (StagePoses); start_gap: clearance(pose), which the caller has measured.
  FingerStage(const StageInputs& inputs, int finger, const FingerAngles& target,
              const FingerCap& cap, FingerBound bound, QpHints& hints, StagePoses& poses,
              HandState& state, HandPose& pose, double start_gap);

  int dofs() const { return FRUSTA_JOINTS_PER_FINGER; }
  double objective() const;
  int32_t row_capacity() const;
  int32_t linearise(QpRow* rows, double* target, double* weights, double radius);
  // the pose's motion bound (finger_motion) of the step d from the last linearisation,
  // over the segments with candidates
  double step_motion(const double* d) const;
  double try_step(const double* d, double s);
  double try_step_anywhere(const double* d);
  double try_between(double s);
  int32_t lazy_rows(const double* d, QpRow* rows) const;

  // The smallest exact gap between this finger and its candidates.
  double clearance(const HandPose& pose) const;

 private:
  // the trial at current + s d, or false where that is beyond the cap
  bool set_trial(const double* d, double s);
  double trial_clearance();  // of the trial state, posed
  // ... of the trial of a step the last linearisation's rows were made for: its contact
  // rows name every candidate such a trial can reach
  double step_clearance();
  // the row of joint j's lower or upper limit, for a step from `now`
  QpRow limit_row(int j, bool lower, const FingerAngles& now) const;
  double row_bound_now() const;  // what the bound's faces keep the move from the start within
  bool beyond_cap(const FingerAngles& next) const;  // further from the start than the cap
  FingerAngles angles(const HandState& state) const;

  const StageInputs inputs_;
  int finger_;
  FingerAngles target_;
  FingerAngles start_;
  FingerCap cap_;
  // what the bound's faces keep the levers' motion within: the cap, by the pose's bound as far
  // as the levers' goes along the move to the target
  double row_cap_;
  // the finger's first-order motion where the stage starts, for its cap's pose bound:
  // made where that can bind (the budget allows more than Delta_r)
  FingerJacobian start_jacobian_;
  FingerBound bound_;
  // the last linearisation's rows (valid until the next) and where each segment's
  // contact rows begin in them
  const QpRow* rows_ = nullptr;
  // the segments with candidates (bit s: segment s): the others have no rows, touch
  // nothing, and their motion bounds nothing
  uint32_t near_ = 0;
  FingerAngles linearised_{};  // where the last linearisation was made
  FingerJacobian jacobian_;    // ... and the first-order motion there of the segments near
  std::array<int32_t, FRUSTA_SEGMENTS_PER_FINGER + 1> segment_rows_{};
};

}  // namespace frusta
