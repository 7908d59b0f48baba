// SPDX-License-Identifier: MIT
#include "solver/palm_stage.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/constraint.h"
#include "geometry/contact_test.h"
#include "solver/stage.h"

namespace frusta {

vec3 rotation_between(const glm::dquat& from, const glm::dquat& to) {
  glm::dquat delta = to * glm::conjugate(from);
  if (delta.w < 0.0) delta = -delta;  // the short way round
  const vec3 v(delta.x, delta.y, delta.z);
  const double sine = glm::length(v);
  if (sine < 1e-300) return vec3(0.0);
  return (2.0 * std::atan2(sine, delta.w) / sine) * v;
}

double palm_motion(const HandReach& reach, const PalmPlacement& from, const PalmPlacement& to) {
  return glm::length(to.position - from.position) +
         glm::length(rotation_between(from.rotation, to.rotation)) * reach.hand;
}

namespace {

PalmPlacement placement(const HandState& state) { return {state.palm_position, state.palm_rotation}; }

glm::dquat rotated(const glm::dquat& q, const vec3& rotation_vector) {
  const double angle = glm::length(rotation_vector);
  if (angle < 1e-300) return q;
  return glm::normalize(glm::angleAxis(angle, rotation_vector / angle) * q);
}

void set_row(QpRow& row, const vec3& grad_translation, const vec3& grad_rotation, double bound,
             int64_t key) {
  for (int k = 0; k < 3; ++k) {
    row.a[k] = grad_translation[k];
    row.a[3 + k] = grad_rotation[k];
  }
  row.b = bound;
  row.key = key;
}

}  // namespace

PalmStage::PalmStage(const StageInputs& inputs, const PalmPlacement& target, double motion_cap,
                     const PalmHeading& heading, bool slide, QpHints& hints, StagePoses& poses,
                     HandState& state, HandPose& pose, double start_gap)
    : StageEstimate(state, pose, hints, poses),
      inputs_(inputs),
      target_(target),
      start_(placement(state)),
      motion_cap_(motion_cap),
      heading_(heading),
      slide_(slide) {
  assert(start_gap == clearance(pose));
  floor_ = std::min(-inputs.params.penetration_tolerance, start_gap);
  recovering_ = start_gap < -kRecoveryTolerances * inputs.params.penetration_tolerance;
}

double PalmStage::objective() const {
  const vec3 to_target = target_.position - state_.palm_position;
  const vec3 turn = rotation_between(state_.palm_rotation, target_.rotation);
  return 0.5 * (inputs_.params.palm_translation_stiffness * glm::dot(to_target, to_target) +
                inputs_.params.palm_rotation_stiffness * glm::dot(turn, turn));
}

int32_t PalmStage::linearise(QpRow* rows, double* target, double* weights, double radius) const {
  const vec3 to_target = target_.position - state_.palm_position;
  const vec3 turn = rotation_between(state_.palm_rotation, target_.rotation);
  for (int k = 0; k < 3; ++k) {
    target[k] = to_target[k];
    target[3 + k] = turn[k];
    weights[k] = inputs_.params.palm_translation_stiffness;
    weights[3 + k] = inputs_.params.palm_rotation_stiffness;
  }
  // a point P carried by the palm moves by dt + dw x (P - palm): g's gradient g_P
  // becomes (g_P, (P - palm) x g_P)
  const vec3& palm = pose_.palm_position;
  // a sphere further than any admissible trial can move is no row: exact, not a guess
  // (and one a step within `radius` cannot reach no row of that step's)
  const double reach =
      std::min(motion_cap_ + palm_motion(inputs_.reach, start_, placement(state_)), radius);
  int32_t count = 0;
  for (int body = 0; body < FRUSTA_HAND_SEGMENT_COUNT; ++body) {
    if (!inputs_.candidates.body_near(body)) continue;
    const SegmentView view = segment_view(inputs_.model, pose_, inputs_.candidates, body);
    const SegmentFrame& frame = view.frame;
    const Candidate* c = inputs_.candidates.of(body);
    for (int32_t i = 0; i < inputs_.candidates.count(body); ++i) {
      if (view.beyond(c[i], reach)) break;  // and every one after
      if (!view.may_touch(c[i], reach)) continue;
      const Constraint g = contact_constraint(frame, c[i].world, inputs_.params.form);
      const double bound = row_bound(
          inputs_.params, g.value, c[i].world.radius + std::max(frame.r_proximal, frame.r_distal));
      set_row(rows[count++], g.grad_proximal + g.grad_distal,
              glm::cross(frame.proximal - palm, g.grad_proximal) +
                  glm::cross(frame.distal - palm, g.grad_distal),
              // a finger a hair deeper than its rows ask is its own stage's to fix: here
              // it only must not get deeper, or the palm would ratchet up a little a
              // step; a hand that started deep is lifted out whole
              recovering_ ? bound : std::min(bound, 0.0),
              row_key(RowKind::kContact, body, c[i].part, c[i].object, c[i].leaf));
    }
  }
  // as for the segments above: a palm with nothing near has no rows
  const int32_t palm_count =
      inputs_.candidates.body_near(kPalmBody) ? inputs_.candidates.count(kPalmBody) : 0;
  const PalmView view =
      palm_count > 0 ? palm_view(inputs_.model, pose_, inputs_.candidates) : PalmView{};
  const Candidate* c = inputs_.candidates.of(kPalmBody);
  for (int32_t i = 0; i < palm_count; ++i) {
    if (view.beyond(c[i], reach)) break;  // and every one after
    if (!view.may_touch(c[i], reach)) continue;
    const Sphere hand = view.sphere(c[i]);
    const vec3 outward = hand.center - palm;
    const SphereConstraint g = sphere_constraint(
        hand, c[i].world, inputs_.params.form,
        glm::length(outward) > 0.0 ? glm::normalize(outward) : vec3(0.0, 0.0, 1.0));
    set_row(rows[count++], g.grad_hand, glm::cross(hand.center - palm, g.grad_hand),
            row_bound(inputs_.params, g.value, hand.radius + c[i].world.radius),
            row_key(RowKind::kContact, kPalmBody, c[i].part, c[i].object, c[i].leaf));
  }
  if (heading_.way != vec3(0.0))
    set_row(rows[count++], heading_.way, vec3(0.0),
            -heading_.slack - glm::dot(heading_.way, state_.palm_position - heading_.from),
            row_key(RowKind::kHeading));
  return count;
}

double PalmStage::step_motion(const double* d) const {
  // a point P carried by the palm moves by dt and turns by |dw| about it: no further
  // than |dt| + |dw| |P - palm| (try_step's rotated)
  return glm::length(vec3(d[0], d[1], d[2])) +
         glm::length(vec3(d[3], d[4], d[5])) * inputs_.reach.hand;
}

int32_t PalmStage::lazy_rows(const double* d, QpRow* rows) const {
  if (!slide_) return 0;
  // the step moves no point further than |dt| + |dw| reach <= |dt|_1 + |dw|_1 reach: that
  // kept within half the bound's rest (the rest left for the next linearisations to
  // press back onto a surface this one stepped off), for every choice of signs, of which
  // d's own bind
  const double rest =
      0.5 * std::max(0.0, motion_cap_ - palm_motion(inputs_.reach, start_, placement(state_)));
  int signs = 0;
  for (int k = 0; k < 6; ++k)
    if (d[k] < 0.0) signs |= 1 << k;
  QpRow row;
  for (int k = 0; k < 6; ++k)
    row.a[static_cast<size_t>(k)] =
        ((signs >> k) & 1 ? 1.0 : -1.0) * (k < 3 ? 1.0 : inputs_.reach.hand);
  row.b = -rest;
  row.key = row_key(RowKind::kMotionBound, signs);
  rows[0] = row;
  return 1;
}

double PalmStage::clearance(const HandPose& pose) const {
  double gap = 0.0;
  for (int body = 0; body < kBodyCount; ++body)
    gap = std::min(gap, body_clearance(inputs_.model, pose, inputs_.candidates, body));
  return gap;
}

double PalmStage::try_step(const double* d, double s) {
  trial_state_ = state_;
  trial_state_.palm_position = state_.palm_position + s * vec3(d[0], d[1], d[2]);
  trial_state_.palm_rotation = rotated(state_.palm_rotation, s * vec3(d[3], d[4], d[5]));
  if (palm_motion(inputs_.reach, start_, placement(trial_state_)) > motion_cap_) {
    capped_ = true;
    return -INFINITY;
  }
  return trial_clearance();
}

double PalmStage::try_between(double s) {
  blend_trial(s);
  return trial_clearance();
}

double PalmStage::trial_clearance() {
  forward_kinematics(inputs_.model, trial_state_, trial_pose_);
  return clearance(trial_pose_);
}

}  // namespace frusta
