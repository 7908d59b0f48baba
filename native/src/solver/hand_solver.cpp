// SPDX-License-Identifier: MIT
#include "solver/hand_solver.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "solver/finger_stage.h"
#include "solver/palm_stage.h"
#include "solver/stage.h"

namespace frusta {

namespace {

// Below this (metres, total_motion) a sub-step or a step did not move the hand.
constexpr double kStandstill = 1e-9;
// Linearisations of a stage that slides (solve_within_budget), each taking half what is
// left of its budget: 63/64 of it in all. With 4 the palm trailed a fingertip rounding a
// 30-degree wedge at 1 m/s further, and closing that trail changed the force by up to
// 0.06 N more than the haptic hand's move accounts for.
constexpr int32_t kSlideIterations = 6;
constexpr int kDeadlineReserveDivisor = 8;
// What a new hand's contact lists hold before they grow, beside its candidates
// (SolverParams::candidate_capacity): at least this many, and a quarter of the
// candidates (a contact is a candidate within the contact distance: the grasp of a
// ball of 10^4 leaves reports up to 35 of 951, one of 10^5 leaves 281 of 8,760)
constexpr int32_t kReservedContacts = 256;
constexpr int32_t kReservedObjects = 64;
// How much larger than a sub-step needs the box is that a broad phase is asked about
// (metres): the hand may move this far before it asks again.
constexpr double kFinderRoom = 0.02;

PalmPlacement placement(const HandState& state) { return {state.palm_position, state.palm_rotation}; }

FingerAngles finger_angles(const HandState& state, int finger) {
  FingerAngles a;
  std::copy_n(state.angles.begin() + finger * FRUSTA_JOINTS_PER_FINGER, a.size(), a.begin());
  return a;
}

void set_finger_angles(HandState& state, int finger, const FingerAngles& a) {
  std::copy(a.begin(), a.end(), state.angles.begin() + finger * FRUSTA_JOINTS_PER_FINGER);
}

// The most any point of the hand moves from state a to state b (a bound).
double hand_motion(const HandReach& reach, const HandState& a, const HandState& b) {
  double finger = 0.0;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    finger =
        std::max(finger, finger_lever_motion(reach, f, finger_angles(a, f), finger_angles(b, f)));
  return palm_motion(reach, placement(a), placement(b)) + finger;
}

// The palm's bound plus every finger's: what a sub-step moved the hand, all told.
double total_motion(const HandReach& reach, const HandState& a, const HandState& b) {
  double motion = palm_motion(reach, placement(a), placement(b));
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    motion += finger_lever_motion(reach, f, finger_angles(a, f), finger_angles(b, f));
  return motion;
}

#ifndef NDEBUG
bool pose_matches(const HandModel& model, const HandState& state, const HandPose& pose) {
  HandPose fresh;
  forward_kinematics(model, state, fresh);
  return bodies_unmoved(fresh, pose) == (1u << kBodyCount) - 1u;
}
#endif

bool same_state(const HandState& a, const HandState& b) {
  return a.palm_position == b.palm_position && a.palm_rotation == b.palm_rotation && a.angles == b.angles;
}

// How far a sub-step's detection looks from a body that may move `motion` in it: as far
// as it can move and still see a contact there (plus the contact distance), up to
// Delta_r. A slow hand, and the segments near the knuckles, meet a fraction of the leaves.
double detection_margin(const SolverParams& params, double motion) {
  return std::min(params.prediction_margin, motion + params.contact_distance);
}

// How much further than a sub-step needs its detection looks, in parts of Delta_r: the
// sub-steps and steps after it take a body's candidates from that walk while the body has
// moved less (CandidateCache). Closing steps of the 10^4-leaf grasp, mean / p99: 80 / 153
// us walking each time, 74 / 148 with a sixteenth of Delta_r, 71 / 143 with a quarter,
// 71 / 139 with half (whose filtering slowed the resting steps by a tenth).
double detection_room(const SolverParams& params) { return 0.25 * params.prediction_margin; }

HandState aimed_at(const HandModel& model, const HandState& haptic) {
  HandState target = haptic;
  target.palm_rotation = glm::normalize(target.palm_rotation);
  clamp_to_limits(model, target);
  return target;
}

}  // namespace

void haptic_hand_pose(const HandModel& model, const HandState& haptic, HandPose& pose) {
  forward_kinematics(model, aimed_at(model, haptic), pose);
}

HandSolver::HandSolver(const HandModel& model, const SolverParams& params)
    : model_(model), params_(params), reach_(hand_reach(model)) {
  forward_kinematics(model_, graphic_, pose_);
  target_pose_ = pose_;
  // a first contact allocates nothing on the 1 kHz thread (CandidateSet::reserve)
  assert(params.candidate_capacity >= 1);  // checked where it entered (check_world_def)
  candidates_.reserve(params.candidate_capacity, kReservedObjects);
  rows_.resize(static_cast<size_t>(params.candidate_capacity));
  near_.resize(static_cast<size_t>(kReservedObjects));
  for (std::vector<SolverContact>* list : {&contacts_, &last_contacts_}) {
    list->resize(static_cast<size_t>(std::max(kReservedContacts, params.candidate_capacity / 4)));
    list->clear();
  }
}

frusta_result HandSolver::check_params(const SolverParams& p, const HandModel& model) {
  double smallest = INFINITY;
  for (const FingerModel& f : model.fingers)
    for (double r : f.radius) smallest = std::min(smallest, r);
  if (!std::isfinite(p.prediction_margin) || !(p.prediction_margin > 0.0) ||
      !(p.prediction_margin < smallest))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "prediction_margin is %g m, must be > 0 and below the smallest finger radius "
                "(%g m) so a sub-step cannot pass through a sphere",
                p.prediction_margin, smallest);
  if (p.form != ConstraintForm::kSquared && p.form != ConstraintForm::kDistance)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "form is %d, must be squared (0) or distance (1)",
                static_cast<int>(p.form));
  for (size_t j = 0; j < p.joint_stiffness.size(); ++j)
    if (!std::isfinite(p.joint_stiffness[j]) || !(p.joint_stiffness[j] > 0.0))
      return fail(FRUSTA_ERROR_OUT_OF_RANGE, "joint_stiffness[%zu] is %g, must be > 0", j,
                  p.joint_stiffness[j]);
  if (!std::isfinite(p.palm_translation_stiffness) || !(p.palm_translation_stiffness > 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "palm_translation_stiffness is %g, must be > 0",
                p.palm_translation_stiffness);
  if (!std::isfinite(p.palm_rotation_stiffness) || !(p.palm_rotation_stiffness > 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "palm_rotation_stiffness is %g, must be > 0",
                p.palm_rotation_stiffness);
  if (!std::isfinite(p.penetration_tolerance) || !(p.penetration_tolerance >= 0.0) ||
      !(p.penetration_tolerance < p.prediction_margin))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "penetration_tolerance is %g m, must be >= 0 and below prediction_margin",
                p.penetration_tolerance);
  if (!std::isfinite(p.contact_distance) || !(p.contact_distance >= 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contact_distance is %g m, must be >= 0",
                p.contact_distance);
  if (!std::isfinite(p.convergence) || !(p.convergence > 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "convergence is %g, must be > 0", p.convergence);
  if (!std::isfinite(p.lod_error) || !(p.lod_error >= 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "lod_error is %g m, must be >= 0", p.lod_error);
  if (!std::isfinite(p.follow_factor) || !(p.follow_factor >= 1.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "follow_factor is %g, must be >= 1 (the graphic hand keeps up with the haptic one)",
                p.follow_factor);
  if (!std::isfinite(p.follow_decay) || !(p.follow_decay >= 0.0) || !(p.follow_decay < 1.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "follow_decay is %g, must be in [0, 1)", p.follow_decay);
  if (!std::isfinite(p.follow_slack) || !(p.follow_slack > 0.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "follow_slack is %g m, must be > 0 (a still haptic hand is still reached)",
                p.follow_slack);
  if (p.tree_level < -1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "tree_level is %d, must be -1 (leaves) or >= 0",
                p.tree_level);
  if (p.max_iterations < 1 || p.qp_iteration_cap < 1 || p.max_substeps < 1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "max_iterations (%d), qp_iteration_cap (%d) and max_substeps (%d) must be >= 1",
                p.max_iterations, p.qp_iteration_cap, p.max_substeps);
  return FRUSTA_OK;
}

frusta_result HandSolver::step(const HandState& haptic, const SolverObject* objects,
                               int32_t object_count, StepStats* stats_out,
                               Clock::time_point deadline, const ObjectFinder* finder,
                               bool objects_as_before) {
  // what the last step's finder found holds for the same finder among the same objects
  if (finder != finder_ || !objects_as_before) found_count_ = -1;
  finder_ = finder;
  // aim short of the deadline by what the work after the last check has lately taken,
  // and at least an eighth of the time left (the first steps that run to it have
  // nothing to go by; a sixteenth still let them end 10-36 us past 700 us)
  deadline_ = deadline == Clock::time_point::max()
                  ? deadline
                  : deadline - std::max(overrun_, (deadline - Clock::now()) / kDeadlineReserveDivisor);
  assert(check_hand_state(haptic, "haptic") == FRUSTA_OK);  // checked where it entered
  StepStats stats;
  const HandState target = aimed_at(model_, haptic);
  // the proxy's bound (SolverParams::follow_factor): as far as the haptic hand moved,
  // and what the deadline kept the last steps from moving; a hand being placed has none
  if (started_)
    recent_move_ = std::max(hand_motion(reach_, last_target_, target), params_.follow_decay * recent_move_);
  double budget = started_ ? params_.follow_factor * recent_move_ + params_.follow_slack + unfinished_
                           : INFINITY;
  heading_ = PalmHeading{};
  const vec3 palm_move = target.palm_position - last_target_.palm_position;
  if (started_ && glm::length(palm_move) > kStandstill)
    heading_ = {graphic_.palm_position, glm::normalize(palm_move), params_.follow_slack};

  if (!started_) {
    // placed where this search began: a search cut by the deadline goes on next step
    // from the same hand, and the graphic hand follows the haptic one from there
    if (!placement_.pending()) placing_ = target;
    HandState start = placing_;
    cache_.clear();  // candidates_, the cache's store, is the search's scratch
    switch (placement_.run(model_, reach_, objects, object_count, params_.penetration_tolerance,
                           tree_cut(), candidates_, deadline_, &start)) {
      case PlacementSearch::Result::kPending:
        stats.lagging = true;  // no graphic hand yet: nothing to touch or feel
        if (stats_out) *stats_out = stats;
        return FRUSTA_OK;
      case PlacementSearch::Result::kNone:
        return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                    "the haptic hand starts inside objects and no placement near it is free");
      case PlacementSearch::Result::kFound:
        break;
    }
    stats.depenetrated = start.palm_position != placing_.palm_position;
    graphic_ = start;
    forward_kinematics(model_, graphic_, pose_);
    unfinished_ = 0.0;
    recent_move_ = 0.0;
    started_ = true;
  }
  // a search for a hand that started inside took this step's budget
  const bool placed = stats.depenetrated;
  settled_.fill(false);
  detected_ = detected_ && objects_as_before;
  if (!objects_as_before) {
    cache_.clear();
    reported_ = false;
  }
  // At rest: the last step left the hand where it found it, and nothing it solved
  // against has changed (its target, the objects, what it detected); only the
  // continuity budget shrank, which cannot free a hand that did not move. The
  // sub-steps would find it there again, and its contacts are the last step's.
  if (resting_ && detected_ && same_state(target, last_target_)) {
    stats.resting = true;
    if (stats_out) *stats_out = stats;
    return FRUSTA_OK;
  }
  // A finger at rest (the last step left it where it found it), aimed where it was in a
  // scene as it was, begins settled: the sub-steps solve it again only if the palm moves.
  // Held still, a grasp had all five fingers solved while one crept on by nanometres.
  if (detected_ && !placed)
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      if (finger_rest_[f] && finger_angles(target, f) == finger_angles(last_target_, f)) {
        settled_[f] = true;
        stats.resting_fingers |= 1u << f;
      }
  const HandState began = graphic_;
  const bool timed = deadline_ != Clock::time_point::max();
  Clock::time_point before = timed ? Clock::now() : Clock::time_point();
  substep_cost_ -= substep_cost_ / 8;  // one slow sub-step (a preemption) fades in a few steps
  for (int32_t sub = 0; sub < params_.max_substeps; ++sub) {
    // The step's last sub-step slides where it is cut short, as one the continuity
    // bound cuts does: a straight cut leaves the hand in the air over a convex edge, its
    // contacts and forces gone until a later step catches up. A sliding sub-step costs
    // up to two plain ones, so on the clock it is the last when two would not fit.
    const bool last = sub + 1 == params_.max_substeps ||
                      (timed && before + 2 * substep_cost_ > deadline_);
    // None starts (but the first, unless a placement took the step) that would not end
    // by the deadline even plain: sub-steps grow dearer as the hand nears more
    // candidates, so the one before may have been costed too cheap to slide as the last.
    if (timed && (sub > 0 || placed) && before + substep_cost_ > deadline_) {
      if (sub == 0) {  // the placement's scratch: no contacts yet
        candidates_.clear();
        detected_ = false;
      }
      stats.lagging = true;
      break;
    }
    bool moved = false;
    const bool reached = substep(target, objects, object_count, last, stats, budget, moved);
    ++stats.substeps;
    if (timed) {
      const Clock::time_point now = Clock::now();
      substep_cost_ = std::max(substep_cost_, now - before);
      before = now;
    }
    if (reached || !moved) break;
    if (last) {  // before the budget: the last sub-step's slide spends all of it
      stats.lagging = true;
      break;
    }
    if (!(budget > kStandstill)) {
      stats.rate_limited = true;
      break;
    }
  }
  unfinished_ = stats.lagging ? budget : 0.0;
  // A hand pressed deep into a curved surface creeps along it as its linearisations
  // converge (linearly: the deep target leaves the surface point weakly determined), a
  // nanometre a step and less for tens of steps; it rests once a step moves it no more
  // (the same for each finger alone: finger_rest_)
  const bool unhindered = !stats.lagging && !stats.rate_limited;
  resting_ = unhindered && !(total_motion(reach_, began, graphic_) > kStandstill);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    finger_rest_[f] =
        unhindered && !(finger_lever_motion(reach_, f, finger_angles(began, f),
                                            finger_angles(graphic_, f)) > kStandstill);
  // (target_pose_ is the last target's: a target held still is posed once)
  if (!same_state(target, last_target_)) forward_kinematics(model_, target, target_pose_);
  last_target_ = target;
  report_contacts();
  if (timed) {  // fades as substep_cost_ does; only a step that ran to its aim adds
    overrun_ -= overrun_ / 8;
    overrun_ = std::max(overrun_, Clock::now() - deadline_);
  }
  if (stats_out) *stats_out = stats;
  return FRUSTA_OK;
}

template <class MakeStage>
StageStats HandSolver::solve_within_budget(MakeStage make, bool budget_binds, bool& slid) {
  if (!budget_binds) {
    auto stage = make(false);
    return solve_stage(stage, params_, rows_);
  }
  const HandState state = graphic_;
  const HandPose pose = pose_;
  auto stage = make(false);
  StageStats stats = solve_stage(stage, params_, rows_);
  if (!stats.capped) return stats;
  // Cut short by its budget: cut short on a straight step towards its target it ends
  // in the air over a convex edge (a step along a surface's tangent lifts off it), its
  // contacts and forces gone for the step. So it slides instead, from where it started,
  // within rows that keep it in its bound (stage.h, lazy_rows).
  graphic_ = state;
  pose_ = pose;
  auto sliding = make(true);
  SolverParams params = params_;  // each linearisation takes half what is left
  params.max_iterations = std::max(params.max_iterations, kSlideIterations);
  // the last of the step's budget: its linearisations stop at the deadline
  const double before = sliding.objective();
  const StageStats slide = solve_stage(sliding, params, rows_, deadline_);
  // Each of its QPs moves closer to the target, but a trial a hair inside a curved
  // surface is pushed back out by the next linearisation, which may cost more than the
  // QP gained: on a coarse ball a fingertip held still slid a few microns towards its
  // target for some steps and then, cut short by its budget, slid back the same way in
  // one, for ever (a hand that never rests and whose forces tremble). A slide that ends
  // further from its target than it began stays where it began.
  if (sliding.objective() > before) {
    graphic_ = state;
    pose_ = pose;
  }
  stats.iterations += slide.iterations;
  stats.qp_iterations += slide.qp_iterations;
  stats.infeasible |= slide.infeasible;
  stats.capped = true;
  slid = true;
  return stats;
}

bool HandSolver::overlaps(const SolverObject& object) {
  detected_ = false;  // candidates_ is the test's scratch (and the cache's store)
  cache_.clear();
  return started_ &&
         !hand_is_free(model_, reach_, pose_, &object, 1, params_.penetration_tolerance, tree_cut(),
                       candidates_);
}

bool HandSolver::substep(const HandState& target, const SolverObject* objects, int32_t object_count,
                         bool last, StepStats& stats, double& budget, bool& moved) {
  const HandState start = graphic_;
  const PalmPlacement palm_from = placement(graphic_), palm_to = placement(target);
  const double palm_move = palm_motion(reach_, palm_from, palm_to);
  const double whole_move = hand_motion(reach_, graphic_, target);

  // the objects a broad phase finds within reach of the whole move: every one that the
  // clearance below could find within its threshold, and the detection within its margin
  // (a smaller one), so both answer as they would over every object
  const int32_t* only = nullptr;
  int32_t only_count = 0;
  if (finder_) {
    const double reach =
        reach_.hand + whole_move + params_.prediction_margin + detection_room(params_);
    const Aabb box{pose_.palm_position - reach, pose_.palm_position + reach};
    if (found_count_ < 0 || !contains(found_box_, box)) {
      // asked with room to spare: in a room of 10^3 props, a query each sub-step of a
      // held grasp (which met ~30 props' fattened boxes) was a twentieth of its step
      found_box_ = {box.lower - kFinderRoom, box.upper + kFinderRoom};
      found_count_ = finder_->find(found_box_, near_.data(), static_cast<int32_t>(near_.size()));
      if (found_count_ > static_cast<int32_t>(near_.size())) {
        near_.resize(static_cast<size_t>(found_count_) * 2);  // more objects near than ever before
        found_count_ = finder_->find(found_box_, near_.data(), static_cast<int32_t>(near_.size()));
      }
      // in index order, as a scan over every object meets them: the same candidates in
      // the same order
      std::sort(near_.begin(), near_.begin() + found_count_);
    }
    only = near_.data();
    only_count = found_count_;
  }

  // nothing within reach of the whole move: go there at once (as far as the budget
  // allows; every point moves in proportion), detecting nothing
  if (bound_clearance(reach_, pose_, objects, object_count, only, only_count) >
      whole_move + params_.prediction_margin) {
    const double s = whole_move > budget ? budget / whole_move : 1.0;
    graphic_ = s < 1.0 ? interpolate(graphic_, target, s) : target;
    forward_kinematics(model_, graphic_, pose_);
    candidates_.clear();
    cache_.clear();
    detected_ = false;
    budget = std::max(0.0, budget - s * whole_move);
    moved = s * whole_move > 0.0;
    return s == 1.0;
  }

  const TreeCut cut = tree_cut();
  // How far each body can move in this sub-step (one recovering looks Delta_r away, below):
  // the palm up to its part of the allowance if it moves at all, a finger segment that
  // and its share of the rest (the stages below keep to these)
  const double allowance = std::min(params_.prediction_margin, budget);
  const double palm_part = palm_move > 0.0
                               ? std::min(0.5 * params_.prediction_margin, allowance)
                               : 0.0;
  DetectionMargins margins;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      margins.body[f * FRUSTA_SEGMENTS_PER_FINGER + s] =
          detection_margin(params_, palm_part + reach_.segment_share[f][s] * (allowance - palm_part));
  margins.body[kPalmBody] = detection_margin(params_, palm_part);
  // A finger that settled in an earlier sub-step of this step (or began it at rest), on a
  // palm that will not move in this one, is not solved again (below): its candidates
  // serve only to find whether it starts inside something and, in the last sub-step, its
  // contacts, for which the spheres within the contact distance suffice.
  DetectionMargins needs = margins;
  if (!(palm_move > 0.0))
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      if (settled_[f])
        for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
          needs.body[f * FRUSTA_SEGMENTS_PER_FINGER + s] = params_.contact_distance;
  cache_.detect(model_, reach_, pose_, objects, object_count, needs, detection_room(params_), cut,
                candidates_, only, only_count);
  detected_ = true;

  // A hand that starts the sub-step inside an object (the host moved the object into
  // it) is solved even where its target has not moved, so it is pushed back out; that
  // may move it Delta_r, so it looks as far
  // (each body's clearance here is also where the stages start from, below)
  std::array<double, kBodyCount> gaps;
  double deepest = 0.0;
  auto measure_gaps = [&] {
    // a body where it stood at the last report, among the same objects, sinks as deep as
    // its deepest reported contact (every pair that sinks is one), else as deep as none
    const uint32_t reported = bodies_as_reported();
    std::array<double, kBodyCount> reported_gaps{};
    if (reported != 0)
      for (const SolverContact& c : contacts_)
        reported_gaps[c.body] = std::min(reported_gaps[c.body], c.distance);
    deepest = 0.0;
    for (int body = 0; body < kBodyCount; ++body) {
      gaps[body] = ((reported >> body) & 1u) != 0
                       ? reported_gaps[body]
                       : body_clearance(model_, pose_, candidates_, body);
      deepest = std::min(deepest, gaps[body]);
    }
  };
  measure_gaps();
  const bool recovering = deepest < -kRecoveryTolerances * params_.penetration_tolerance;
  const DetectionMargins everywhere(params_.prediction_margin);
  if (recovering && needs.body != everywhere.body) {
    stats.tree_nodes_visited += candidates_.tree_nodes_visited;
    cache_.detect(model_, reach_, pose_, objects, object_count, everywhere, detection_room(params_),
                  cut, candidates_, only, only_count);
    measure_gaps();
  }
  stats.candidates = std::max(stats.candidates, candidates_.size());
  stats.tree_nodes_visited += candidates_.tree_nodes_visited;
  const StageInputs inputs{model_, reach_, params_, candidates_};
  bool reached = true;
  auto add = [&](const StageStats& s) {
    stats.iterations += s.iterations;
    stats.qp_iterations += s.qp_iterations;
    stats.infeasible |= s.infeasible;
    reached &= !s.capped;
  };
  // how far any point may move in this sub-step: Delta_r (half of it for the palm), and
  // the continuity budget, which an object pushing the hand out does not spend (the
  // haptic hand did not move it)
  const double allowed =
      recovering ? params_.prediction_margin : std::min(params_.prediction_margin, budget);
  const double cap = std::min(0.5 * params_.prediction_margin, allowed);
  // this sub-step is the step's last whole one: a stage cut short now stays short
  const bool budget_binds = !recovering && (last || budget < params_.prediction_margin);
  bool slid = false;

  // A part with candidates solves towards its full target and its stage stops at the
  // motion bound; a part with none moves straight, cut at the bound.
  if (palm_move > 0.0 || recovering) {
    if (candidates_.near == 0) {
      const double s = std::min(1.0, cap / palm_move);
      graphic_.palm_position = s < 1.0 ? palm_from.position + s * (palm_to.position - palm_from.position)
                                       : palm_to.position;
      graphic_.palm_rotation = s < 1.0 ? glm::slerp(palm_from.rotation, palm_to.rotation, s)
                                       : palm_to.rotation;
      reached &= s == 1.0;
      forward_kinematics(model_, graphic_, pose_);
    } else {
      add(solve_within_budget(
          [&](bool slide) {
            return PalmStage(inputs, palm_to, cap, recovering ? PalmHeading{} : heading_, slide,
                             palm_hints_, stage_poses_, graphic_, pose_, deepest);
          },
          budget_binds, slid));
      ++stats.palm_solves;
    }
  }

  // the fingers may use whatever of Delta_r the palm left; a finger that settled in an
  // earlier sub-step on a palm that has not moved since would solve the same problem
  // again, so it is skipped
  const double palm_moved_by = palm_motion(reach_, palm_from, placement(graphic_));
  // by the levers, the budget (none when recovering); by the pose, Delta_r: the margins
  // above hold a segment's move under either
  const FingerCap finger_cap{(recovering ? INFINITY : budget) - palm_moved_by,
                             params_.prediction_margin - palm_moved_by};
  const bool palm_moved = palm_moved_by > 0.0;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    if (settled_[f] && !palm_moved && !recovering) continue;
    const FingerAngles from = finger_angles(graphic_, f), to = finger_angles(target, f);
    const double move = finger_lever_motion(reach_, f, from, to);
    settled_[f] = true;
    if (!(move > 0.0) && !recovering) continue;
    const double share = within_cap(model_, reach_, pose_.fingers[f], f, from, to, finger_cap);
    if (!candidates_.finger_near(f)) {  // nothing near: the haptic angles as they are
      FingerAngles goal = to;
      if (share < 1.0) {
        for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
          goal[j] = from[j] + share * (to[j] - from[j]);
        reached = false;
        settled_[f] = false;
      }
      set_finger_angles(graphic_, f, goal);
      finger_kinematics(model_, graphic_, f, pose_);
      continue;
    }
    // a target beyond the cap: the best step the cap allows (FingerBound::kTrust)
    const FingerBound bound = share < 1.0 ? FingerBound::kTrust : FingerBound::kHalve;
    // where the palm has not moved, the finger is where the sub-step began
    double start_gap = 0.0;
    if (palm_moved)
      start_gap = finger_clearance(model_, pose_, candidates_, f);
    else
      for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
        start_gap = std::min(start_gap, gaps[f * FRUSTA_SEGMENTS_PER_FINGER + s]);
    const StageStats finger_stats = solve_within_budget(
        [&](bool slide) {
          return FingerStage(inputs, f, to, finger_cap, slide ? FingerBound::kSlide : bound,
                             finger_hints_[static_cast<size_t>(f)], stage_poses_, graphic_, pose_,
                             start_gap);
        },
        budget_binds, slid);
    add(finger_stats);
    settled_[f] = !finger_stats.capped;
    ++stats.finger_solves;
  }
  // every stage left the pose of what it moved (a whole hand's kinematics after each
  // finger was a tenth of a trembling grasp's step)
  assert(pose_matches(model_, graphic_, pose_));

  moved = total_motion(reach_, start, graphic_) > kStandstill;
  if (!recovering) budget = std::max(0.0, budget - hand_motion(reach_, start, graphic_));
  if (slid) budget = 0.0;  // it went as far as it could on the surface: the step ends
  return reached && !slid;
}

void HandSolver::report_contacts() {
  // A body where it stood at the last report, among the same objects, has the same
  // contacts: held, a grasp's resting fingers measured theirs again every step.
  std::swap(contacts_, last_contacts_);
  contacts_.clear();
  const uint32_t unmoved = bodies_as_reported();
  size_t last = 0;  // where the body's run of the last report begins (they are by body)
  for (int body = 0; body < kBodyCount; ++body) {
    const size_t first = contacts_.size();
    const double within = std::min(params_.contact_distance, candidates_.need[body]);
    size_t last_end = last;
    while (last_end < last_contacts_.size() && last_contacts_[last_end].body == body) ++last_end;
    const bool again = ((unmoved >> body) & 1u) != 0 && within == reported_within_[body];
    if (again)
      contacts_.insert(contacts_.end(), last_contacts_.begin() + static_cast<std::ptrdiff_t>(last),
                       last_contacts_.begin() + static_cast<std::ptrdiff_t>(last_end));
    last = last_end;
    reported_within_[body] = within;
    if (again || !candidates_.body_near(body)) continue;
    if (body == kPalmBody) {
      const PalmView view = palm_view(model_, pose_, candidates_);
      report_body(body, view, within,
                  [&](const Candidate& c) { return exact_proximity(view.sphere(c), c.world); });
    } else {
      const SegmentView view = segment_view(model_, pose_, candidates_, body);
      report_body(body, view, within,
                  [&](const Candidate& c) { return exact_proximity(view.frame, c.world); });
    }
    // in an order of their own, not of the candidates (of where each walk looked from):
    // the same hand and objects make the same list, and the forces summed over it the
    // same bits. By body, then object, leaf and palm sphere: a body's are sorted apart.
    std::sort(contacts_.begin() + static_cast<std::ptrdiff_t>(first), contacts_.end(),
              [](const SolverContact& a, const SolverContact& b) {
                return std::tie(a.object, a.leaf, a.part, a.object_point.x, a.object_point.y,
                                a.object_point.z) < std::tie(b.object, b.leaf, b.part,
                                                             b.object_point.x, b.object_point.y,
                                                             b.object_point.z);
              });
  }
  reported_pose_ = pose_;
  reported_ = true;
}

template <class View, class Measure>
void HandSolver::report_body(int body, const View& view, double within, Measure measure) {
  const Candidate* c = candidates_.of(body);
  const int32_t count = candidates_.count(body);
  for (int32_t i = 0; i < count; ++i) {
    // candidates further than the contact distance, most of them, are told by their gap
    // bounds before a contact is begun
    if (view.beyond(c[i], within)) break;  // and all after
    if (!view.may_touch(c[i], within)) continue;
    const Proximity p = measure(c[i]);
    if (!(p.distance <= within)) continue;
    SolverContact contact;
    contact.object = c[i].object;
    contact.leaf = c[i].leaf;
    contact.body = body;
    contact.part = c[i].part;
    contact.distance = p.distance;
    contact.hand_point = p.hand_point;
    contact.object_point = p.object_point;
    contact.normal = p.normal;
    contacts_.push_back(contact);
  }
}

}  // namespace frusta
