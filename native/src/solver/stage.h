// SPDX-License-Identifier: MIT
// The iteration every stage shares (seed [0143]): linearise the constraints at the
// current estimate, solve the QP, take the longest step (halving) that keeps the true
// geometry apart and the motion within its bound, and repeat until nothing moves.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "hand/kinematics.h"
#include "solver/detection.h"
#include "solver/qp.h"
#include "solver/solver_params.h"

namespace frusta {

struct StageStats {
  int32_t iterations = 0;     // linearisations that moved the estimate
  int32_t qp_iterations = 0;  // active-set changes over all QPs
  bool infeasible = false;    // some QP had no point meeting every linearised row
  bool capped = false;        // a step was cut short by the stage's motion bound
};

// What the palm and finger stages of a sub-step solve against, the same for each.
struct StageInputs {
  const HandModel& model;
  const HandReach& reach;
  const SolverParams& params;
  const CandidateSet& candidates;
};

// Where a stage poses its trials and keeps its last safe estimate: the caller's, kept
// between stages, so that a finger's stage copies in the palm's and its finger's parts
// only rather than two whole hands (1.9 KB each, 1.4 % of a closing step). One stage uses
// them at a time.
struct StagePoses {
  HandPose trial, saved;
};

// What every stage keeps besides its problem: the graphic hand it updates in place, a
// trial and the last estimate that sank no deeper than its floor (the Problem half
// of solve_stage below). A finger's stage moves that finger alone: its poses differ from
// the one it started at in that finger only, which is all they copy (a whole hand's pose
// is 1.9 KB, and its copies were a twentieth of a closing step).
class StageEstimate {
 public:
  // hints: what this part's QPs ended with active, kept from one to the next (QpHints);
  // poses: where it poses its trials; finger: the finger the stage moves, or -1 for the
  // whole hand
  StageEstimate(HandState& state, HandPose& pose, QpHints& hints, StagePoses& poses, int finger = -1)
      : state_(state),
        pose_(pose),
        trial_state_(state),
        saved_state_(state),
        trial_pose_(poses.trial),
        saved_pose_(poses.saved),
        hints_(hints),
        finger_only_(finger) {
    // a finger's trials read the palm's placement and write that finger alone
    trial_pose_.palm_position = saved_pose_.palm_position = pose.palm_position;
    trial_pose_.palm_rotation = saved_pose_.palm_rotation = pose.palm_rotation;
    copy_pose(pose, trial_pose_);
    copy_pose(pose, saved_pose_);
  }

  double floor() const { return floor_; }
  QpHints& hints() { return hints_; }
  bool capped() const { return capped_; }
  void commit() {
    state_ = trial_state_;
    copy_pose(trial_pose_, pose_);
  }
  void save() {
    saved_state_ = state_;
    copy_pose(pose_, saved_pose_);
  }
  void restore() {
    state_ = saved_state_;
    copy_pose(saved_pose_, pose_);
  }
  // the trial a fraction s of the way from the last saved estimate to the current one
  void blend_trial(double s) { trial_state_ = interpolate(saved_state_, state_, s); }

 protected:
  HandState& state_;
  HandPose& pose_;
  HandState trial_state_, saved_state_;
  HandPose &trial_pose_, &saved_pose_;
  double floor_ = 0.0;    // a trial may not sink below this gap
  bool capped_ = false;   // some trial was refused for moving too far
  QpHints& hints_;

 private:
  void copy_pose(const HandPose& from, HandPose& to) const {
    if (finger_only_ < 0) {
      to = from;
      return;
    }
    to.fingers[static_cast<size_t>(finger_only_)] = from.fingers[static_cast<size_t>(finger_only_)];
  }
  int finger_only_;
};

// A linearised row's name (QpRow::key), the same in every linearisation and step: its
// kind and what it stands for, mixed into 64 bits (a clash only misleads a hint).
enum class RowKind : int64_t { kJointLimit = 1, kMotionBound = 2, kContact = 3, kHeading = 4 };
inline int64_t row_key(RowKind kind, int64_t a = 0, int64_t b = 0, int64_t c = 0, int64_t d = 0) {
  uint64_t key = static_cast<uint64_t>(kind);
  for (int64_t part : {a, b, c, d}) key = key * 0x100000001b3ull + static_cast<uint64_t>(part);
  return static_cast<int64_t>(key | 1ull);  // never 0, which names nothing
}

// The bound of a linearised row, g + a.d >= bound. Rows ask for half the penetration
// tolerance, so a hand one stage left inside the tolerance is not pushed back out by
// the next (that ratchets: the palm rose a micron a step under fingers pressing down).
// `reach` scales the slack into the squared form's units (dg/d|OC| = 2 |OC|).
inline double row_bound(const SolverParams& params, double value, double reach) {
  const double scale = params.form == ConstraintForm::kDistance ? 1.0 : 2.0 * reach;
  return -value - 0.5 * params.penetration_tolerance * scale;
}

// Problem: int dofs(); int32_t row_capacity(); double floor() (the least gap allowed);
//   int32_t linearise(QpRow* rows, double* target, double* weights, double radius): rows,
//     target and weights for the step d from the current estimate: the rows of every
//     sphere that a step moving the hand no further than `radius` (step_motion) may reach,
//     and at least those of every sphere an admissible trial may reach when it is infinite;
//   double step_motion(const double* d): no point of the part near its candidates moves
//     further in the step d from where linearise was made (the unit of `radius`);
//   double try_step(const double* d, double s): the smallest gap at current + s d, or
//     -infinity when that moves the hand further than the stage allows (a finger's over
//     the spheres of the last linearisation's rows, which name every sphere a step
//     within its radius can reach);
//   double try_step_anywhere(const double* d): the same for the whole step d over every
//     candidate, for a step beyond its rows' radius;
//   double try_between(double s): the same for the trial a fraction s of the way from
//     the last estimate save() kept to the current one;
//   int32_t lazy_rows(const double* d, QpRow* rows): rows the step d may lie beyond,
//     made only for the steps that reach them (QpLazyRows, at most kMaxLazyRowsAtOnce):
//     the joint limits d passes, and for a stage that steps within rows keeping it in its
//     motion bound (one sliding, a finger aimed beyond its cap) the face of that bound d
//     lies beyond (one of at most 2^6);
//   bool capped(): whether some trial was refused for moving too far (or, stepping
//     within bound rows, stopped at the cap by them);
//   void commit(): make the last trial the current estimate;
//   void save() / restore(): keep / return to an estimate that meets floor().
//
// Steps are taken whole (SQP converges fast that way) even when the curvature the
// linearisation missed leaves a trial a hair inside an object: the next linearisation
// pulls it back out. Only a trial deeper than kWorkingDepth is halved. If the last
// estimate still sinks below floor(), the stage ends at the furthest point that does
// not on the way to it from the last estimate that did (bisected): ending at that last
// estimate itself dropped the whole move whenever the rows' linearisation missed, for
// instance where a small leaf on a sharp edge crosses the crease between a segment's
// side and its end ball; the hand then stood still while the haptic hand moved on, and
// jumped when a step at last landed clear (8 mm in a step on a 30-degree wedge).
constexpr int kMaxHalvings = 16;  // 2^-16 of a step is not worth re-linearising for
constexpr int kBisections = 8;  // 1/256 of the last step: less is not worth its cost
// the rows a QP may make lazily: the palm's 2^6 faces of its motion bound, a finger's
// 2^4 and its 8 joint limits
constexpr int32_t kMaxLazyRows = 64;
constexpr double kWorkingDepth = 2.5e-4;  // metres
// A linearisation makes only the rows of spheres a step of a guessed size can reach;
// where its step goes further, it is kept if it ends clear of every candidate, else
// made again for that step (solve_stage). The rows of every sphere a whole step could
// reach were 150-250 a finger on the 10^4-leaf grasp, most of a linearisation's and its
// QP's time. A linearisation after the first guesses a part of the step before (it
// corrects that step for the curvature it missed, and moved 2-20 % of it there, a few
// times 45 %); a stage's first, a part of its part's last first step
// (QpHints::first_step). While a step beyond the guess was always made again, the best
// guesses were the step before and twice the last first step (closing steps of that
// grasp 127 -> 99 us); keeping a clear step, a quarter of each (instructions over its
// 500 steps 79.5 -> 67.5 M, half of each 69.3 M, a tenth of the step before 68.2 M).
// Timed since, steps of two builds alternated in one process: an eighth of the step
// before took the grasp's 30 dearest steps 1.7 % less time than a quarter (a tenth and
// three sixteenths no better, a quarter of the first step still the best).
constexpr double kRowRadius = 0.125;
constexpr double kFirstRowRadius = 0.25;
// A linearisation whose step went beyond its radius was made again with every row (90
// a time in that grasp's closing, against 16 in the guess), though nine in ten of those
// steps went less than 4 times the radius: it is made again for a step 1.5 times the
// one found (30 rows; none in the grasp went beyond that too). Closing steps 49.2 ->
// 45.8 us, the same hand bit for bit; 1.25 or 2 times: the same within 1 %.
constexpr double kRedoRadius = 1.5;

// A hand held back by its budget steps within rows that keep it inside its bound
// (sliding as far as they allow, pressed on the surface by the target behind it), rather
// than towards its target cut short (off the surface, in the air). The bound's faces are
// 2^dofs rows of which a step meets one, and a step meets few joint limits, so the QP
// makes those rows as its answers reach them (QpLazyRows): 16 faces and 8 limits were
// 24 of a finger QP's 36 rows on the 10^4-leaf grasp, scanned at every change of its
// active set and almost never met.
template <class Problem>
QpLazyRows lazy_rows(const Problem& problem) {
  return {[](const void* p, const double* d, QpRow* rows) {
            return static_cast<const Problem*>(p)->lazy_rows(d, rows);
          },
          &problem, kMaxLazyRows};
}

// `deadline`: a linearisation that, at the average cost of this stage's so far, would
// end after it does not start (the first always runs). Each one ends at a checked trial,
// so a stage cut there is as safe as a finished one, only shorter.
template <class Problem>
StageStats solve_stage(Problem& problem, const SolverParams& params, std::vector<QpRow>& rows,
                       std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max()) {
  using Clock = std::chrono::steady_clock;
  const bool timed = deadline != Clock::time_point::max();
  const Clock::time_point started = timed ? Clock::now() : Clock::time_point();
  StageStats stats;
  const int n = problem.dofs();
  const size_t capacity = static_cast<size_t>(problem.row_capacity() + kMaxLazyRows);
  if (rows.size() < capacity) rows.resize(capacity);
  const double working_floor = std::min(problem.floor(), -kWorkingDepth);
  bool safe = true;
  problem.save();
  double target[kMaxQpVariables] = {}, weights[kMaxQpVariables] = {};
  auto solve_within = [&](double radius, double* d) {
    const int32_t count = problem.linearise(rows.data(), target, weights, radius);
    problem.hints().mark(rows.data(), count);
    const QpResult qp = solve_projection_qp(n, weights, target, rows.data(), count,
                                            params.qp_iteration_cap, d, lazy_rows(problem));
    problem.hints().keep(rows.data(), qp);
    stats.qp_iterations += qp.iterations;
    return qp;
  };
  double radius = kFirstRowRadius * problem.hints().first_step;
  for (int32_t it = 0; it < params.max_iterations; ++it) {
    if (timed && it > 0) {
      const Clock::time_point now = Clock::now();
      if (now + (now - started) / it > deadline) break;
    }
    double d[kMaxQpVariables] = {};
    QpResult qp = solve_within(radius, d);
    double motion = problem.step_motion(d);
    // An optimum within the radius is the one every row makes: the rows left out are
    // of spheres further than it moves the hand, met there, and the QP is convex. One
    // beyond it that ends clear of every candidate (exactly, not by rows) is kept: the
    // rows left out could only have held it further from its target, short of spheres
    // it does not reach. Any other is made again with the rows a step kRedoRadius times
    // its length can reach, and one beyond that, or none, with every row.
    double gap = -INFINITY;
    bool kept = false;
    if (radius < INFINITY && qp.status == QpStatus::kOptimal && motion > radius) {
      gap = problem.try_step_anywhere(d);
      kept = gap >= problem.floor();
    }
    for (int redo = 0; !kept && radius < INFINITY && (qp.status != QpStatus::kOptimal || motion > radius); ++redo) {
      radius = redo == 0 && qp.status == QpStatus::kOptimal ? kRedoRadius * motion : INFINITY;
      qp = solve_within(radius, d);
      motion = problem.step_motion(d);
    }
    stats.infeasible |= qp.status == QpStatus::kInfeasible;
    double largest = 0.0;
    for (int j = 0; j < n; ++j) largest = std::max(largest, std::fabs(d[j]));
    if (!(largest > params.convergence)) break;
    double s = 1.0;
    if (!kept) gap = problem.try_step(d, s);
    for (int halving = 0; !(gap >= working_floor) && halving < kMaxHalvings; ++halving) {
      s *= 0.5;
      gap = problem.try_step(d, s);
    }
    if (!(gap >= working_floor)) break;  // the current estimate is as far as it goes
    problem.commit();
    ++stats.iterations;
    const double stepped = s * motion;
    radius = kRowRadius * stepped;
    if (it == 0) problem.hints().first_step = stepped;
    safe = gap >= problem.floor();
    if (safe) problem.save();
    if (!(largest * s > params.convergence)) break;
  }
  if (!safe) {
    double reached = 0.0, beyond = 1.0;  // fractions of the way: clear, and not
    bool posed = false;  // the trial is the one at `reached` (the last was clear)
    for (int halving = 0; halving < kBisections; ++halving) {
      const double s = 0.5 * (reached + beyond);
      posed = problem.try_between(s) >= problem.floor();
      (posed ? reached : beyond) = s;
    }
    if (reached > 0.0 && (posed || problem.try_between(reached) >= problem.floor()))
      problem.commit();
    else
      problem.restore();
  }
  stats.capped = problem.capped();
  return stats;
}

}  // namespace frusta
