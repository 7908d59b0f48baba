// SPDX-License-Identifier: MIT
#include "solver/finger_stage.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/constraint.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "solver/stage.h"

namespace frusta {

FingerStage::FingerStage(const StageInputs& inputs, int finger, const FingerAngles& target,
                         const FingerCap& cap, FingerBound bound, QpHints& hints,
                         StagePoses& poses, HandState& state, HandPose& pose, double start_gap)
    : StageEstimate(state, pose, hints, poses, finger),
      inputs_(inputs),
      finger_(finger),
      target_(target),
      start_(angles(state)),
      cap_(cap),
      row_cap_(std::min(cap.levers, cap.pose)),
      bound_(bound) {
  // never worse than the start, which a rounding or a curvature may have left a hair deep
  assert(start_gap == clearance(pose));
  floor_ = std::min(-inputs.params.penetration_tolerance, start_gap);
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
    if (inputs.candidates.body_near(finger * FRUSTA_SEGMENTS_PER_FINGER + s)) near_ |= 1u << s;
  if (cap.levers > cap.pose) {
    finger_jacobian(pose.fingers[finger], kEverySegment, start_jacobian_);
    // Rows bound the levers' motion (linear in the step); the pose's bound lets a finger
    // further, by as much as the levers' bound exceeds it on a step of the cap's size
    // towards the target (a step elsewhere that goes past the cap is refused, and halved)
    const double levers = finger_lever_motion(inputs.reach, finger, start_, target);
    if (levers > cap.pose) {
      FingerAngles turn;
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
        turn[j] = (cap.pose / levers) * (target[j] - start_[j]);
      const double posed =
          finger_motion(inputs.model, inputs.reach, start_jacobian_, finger, turn, kEverySegment);
      if (posed > 0.0) row_cap_ = std::min(cap.levers, cap.pose * cap.pose / posed);
    }
  }
}

FingerAngles FingerStage::angles(const HandState& state) const {
  FingerAngles a;
  std::copy_n(state.angles.begin() + finger_ * FRUSTA_JOINTS_PER_FINGER, a.size(), a.begin());
  return a;
}

double FingerStage::objective() const {
  const FingerAngles now = angles(state_);
  double sum = 0.0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    sum += inputs_.params.joint_stiffness[j] * (target_[j] - now[j]) * (target_[j] - now[j]);
  return 0.5 * sum;
}

int32_t FingerStage::row_capacity() const {
  return inputs_.candidates.finger_count(finger_) + 2 * FRUSTA_JOINTS_PER_FINGER;
}

int32_t FingerStage::linearise(QpRow* rows, double* target, double* weights, double radius) {
  const FingerAngles now = angles(state_);
  int32_t count = 0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
    target[j] = target_[j] - now[j];
    weights[j] = inputs_.params.joint_stiffness[j];
    // a joint limit is made where a step passes it (lazy_rows), or here where the last QP
    // ended on it: listed, it joins first (QpHints), as it did then
    for (int side = 0; side < 2; ++side)
      if (hints_.names(row_key(RowKind::kJointLimit, j, side)))
        rows[count++] = limit_row(j, side == 0, now);
  }
  rows_ = rows;
  linearised_ = now;
  finger_jacobian(pose_.fingers[finger_], near_, jacobian_);
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
    const int body = finger_ * FRUSTA_SEGMENTS_PER_FINGER + s;
    segment_rows_[static_cast<size_t>(s)] = count;
    if (!inputs_.candidates.body_near(body)) continue;
    const SegmentView view = segment_view(inputs_.model, pose_, inputs_.candidates, body);
    const SegmentFrame& frame = view.frame;
    // a sphere further than any admissible trial can move the segment is no row: exact,
    // not a guess (a trial moves the finger within the cap from the start, and the
    // segment by at most its share of that)
    // (and one a step within `radius` cannot reach no row of that step's)
    const double share = inputs_.reach.segment_share[finger_][s];
    const double reach = std::min(share * std::min(cap_.levers, cap_.pose) +
                                      segment_lever_motion(inputs_.reach, finger_, s, start_, now),
                                  share * radius);
    const auto& column_d = jacobian_.proximal[s];  // dD/dq, D = joint s
    const auto& column_e = jacobian_.distal[s];    // dE/dq, E = joint s + 1
    const Candidate* c = inputs_.candidates.of(body);
    // (the count and the first index read once: the rows written may alias them)
    const int32_t first = inputs_.candidates.begin[body],
                  candidates = inputs_.candidates.count(body);
    for (int32_t i = 0; i < candidates; ++i) {
      if (view.beyond(c[i], reach)) break;  // and every one after
      if (!view.may_touch(c[i], reach)) continue;
      const Constraint g = contact_constraint(frame, c[i].world, inputs_.params.form);
      QpRow& row = rows[count++];
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
        row.a[j] = glm::dot(g.grad_proximal, column_d[j]) + glm::dot(g.grad_distal, column_e[j]);
      for (int j = FRUSTA_JOINTS_PER_FINGER; j < kMaxQpVariables; ++j) row.a[j] = 0.0;
      row.b = row_bound(inputs_.params, g.value,
                        c[i].world.radius + std::max(frame.r_proximal, frame.r_distal));
      row.key = row_key(RowKind::kContact, body, c[i].part, c[i].object, c[i].leaf);
      row.source = first + i;
    }
  }
  segment_rows_[FRUSTA_SEGMENTS_PER_FINGER] = count;
  return count;
}

double FingerStage::step_motion(const double* d) const {
  // from where the rows were made, within the joints' limits as try_step takes it: a
  // joint held at its limit no longer turns against the others, as the pose's bound counts
  const FingerModel& finger = inputs_.model.fingers[finger_];
  FingerAngles turn;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    turn[j] = std::clamp(linearised_[j] + d[j], finger.joint_min[j], finger.joint_max[j]) -
              linearised_[j];
  return finger_motion(inputs_.model, inputs_.reach, jacobian_, finger_, turn, near_);
}

double FingerStage::row_bound_now() const {
  // trusting: the cap itself, a hair inside so that rounding cannot refuse the step
  if (bound_ == FingerBound::kTrust) return (1.0 - 1e-9) * row_cap_;
  // sliding: half the cap's rest, the rest left for the next linearisations to press
  // back onto a surface this one stepped off
  const double moved = finger_lever_motion(inputs_.reach, finger_, start_, angles(state_));
  return moved + 0.5 * std::max(0.0, row_cap_ - moved);
}

QpRow FingerStage::limit_row(int j, bool lower, const FingerAngles& now) const {
  const FingerModel& finger = inputs_.model.fingers[finger_];
  QpRow row;
  row.a[static_cast<size_t>(j)] = lower ? 1.0 : -1.0;
  row.b = lower ? finger.joint_min[j] - now[j] : now[j] - finger.joint_max[j];
  row.key = row_key(RowKind::kJointLimit, j, lower ? 0 : 1);
  return row;
}

int32_t FingerStage::lazy_rows(const double* d, QpRow* rows) const {
  const FingerAngles now = angles(state_);
  const FingerModel& finger = inputs_.model.fingers[finger_];
  int32_t count = 0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
    const bool below = now[j] + d[j] < finger.joint_min[j];
    if (below || now[j] + d[j] > finger.joint_max[j])
      rows[count++] = limit_row(j, below, now);
  }
  if (bound_ == FingerBound::kHalve) return count;
  // finger_motion(start, now + d) <= bound exactly: sum_j lever_j s_j (now_j + d_j -
  // start_j) <= bound for every choice of signs s, of which d's own signs bind
  QpRow row;
  int signs = 0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    if (now[j] + d[j] - start_[j] < 0.0) signs |= 1 << j;
  row.b = -row_bound_now();
  row.key = row_key(RowKind::kMotionBound, signs);
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
    const double s = (signs >> j) & 1 ? -1.0 : 1.0;
    const double lever = inputs_.reach.lever[finger_][j];
    row.a[static_cast<size_t>(j)] = -s * lever;
    row.b += s * lever * (now[j] - start_[j]);
  }
  rows[count++] = row;
  return count;
}

double finger_clearance(const HandModel& model, const HandPose& pose,
                        const CandidateSet& candidates, int finger) {
  double gap = 0.0;
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
    gap = std::min(
        gap, body_clearance(model, pose, candidates, finger * FRUSTA_SEGMENTS_PER_FINGER + s));
  return gap;
}

double FingerStage::clearance(const HandPose& pose) const {
  return finger_clearance(inputs_.model, pose, inputs_.candidates, finger_);
}

bool FingerStage::set_trial(const double* d, double s) {
  const FingerModel& finger = inputs_.model.fingers[finger_];
  FingerAngles next = angles(state_);
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    next[j] = std::clamp(next[j] + s * d[j], finger.joint_min[j], finger.joint_max[j]);
  if (beyond_cap(next)) {
    capped_ = true;
    return false;
  }
  // a step the rows stopped at the cap: the stage did not reach its target
  if (bound_ == FingerBound::kTrust &&
      finger_lever_motion(inputs_.reach, finger_, start_, next) >= (1.0 - 1e-6) * row_cap_)
    capped_ = true;
  trial_state_ = state_;
  std::copy(next.begin(), next.end(), trial_state_.angles.begin() + finger_ * FRUSTA_JOINTS_PER_FINGER);
  return true;
}

double FingerStage::try_step(const double* d, double s) {
  return set_trial(d, s) ? step_clearance() : -INFINITY;
}

double FingerStage::try_step_anywhere(const double* d) {
  return set_trial(d, 1.0) ? trial_clearance() : -INFINITY;
}

bool FingerStage::beyond_cap(const FingerAngles& next) const {
  // (the pose's bound is needed, and start_jacobian_ made, only where cap_.levers > cap_.pose)
  return within_cap(inputs_.model, inputs_.reach, start_jacobian_, finger_, start_, next, cap_) <
         1.0;
}

double FingerStage::try_between(double s) {
  // this finger's angles alone: a blend of the whole hand turns the palm by a rounding
  // (a slerp between equal rotations), which this finger's pose would not follow
  const FingerAngles from = angles(saved_state_), to = angles(state_);
  FingerAngles blend;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) blend[j] = from[j] + s * (to[j] - from[j]);
  // both ends keep to the cap, but the pose's bound is not convex: a blend may not
  if (beyond_cap(blend)) return -INFINITY;
  trial_state_ = state_;
  std::copy(blend.begin(), blend.end(),
            trial_state_.angles.begin() + finger_ * FRUSTA_JOINTS_PER_FINGER);
  return trial_clearance();
}

double FingerStage::trial_clearance() {
  // (the rest of the trial's pose is the stage's, as the finger's kinematics rewrite it whole)
  finger_kinematics(inputs_.model, trial_state_, finger_, trial_pose_);
  return clearance(trial_pose_);
}

double FingerStage::step_clearance() {
  // A sphere that made no row lies further from its segment than the step can move it
  // (linearise's reach; a step beyond its radius was linearised again for a radius it
  // keeps within), so it cannot touch: the same gap as every candidate's, from the few near
  finger_kinematics(inputs_.model, trial_state_, finger_, trial_pose_);
  double gap = 0.0;
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
    const int32_t begin = segment_rows_[static_cast<size_t>(s)];
    gap = std::min(gap, body_clearance_over(inputs_.model, trial_pose_, inputs_.candidates,
                                            finger_ * FRUSTA_SEGMENTS_PER_FINGER + s,
                                            segment_rows_[static_cast<size_t>(s) + 1] - begin,
                                            [&](int32_t k) { return rows_[begin + k].source; }));
  }
  return gap;
}

}  // namespace frusta
