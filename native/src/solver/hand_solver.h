// SPDX-License-Identifier: MIT
// The graphic hand (seed [0131]-[0156]): each step takes the haptic hand, which may be
// deep inside objects, and moves the graphic hand as close to it as the objects allow,
// never into them. Per sub-step: detect from the graphic hand with radii inflated by
// Delta_r, solve the palm (if it moves) and then each finger with candidates near it;
// a finger with none takes the haptic angles as they are.
//
// Fast motion: within a sub-step no hand point moves more than Delta_r (at most half
// for the palm, the rest for a finger), and every object sphere within Delta_r is a
// constraint, so
// nothing the hand can reach in a sub-step is missed; passing through a sphere would
// need a move of twice the hand's smallest radius, more than Delta_r. A move that
// needs more sub-steps than allowed finishes on later steps.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

#include "solver/broad_phase.h"
#include "solver/candidate_cache.h"
#include "solver/depenetration.h"
#include "solver/detection.h"
#include "solver/palm_stage.h"
#include "solver/solver_params.h"
#include "solver/qp.h"
#include "solver/stage.h"

namespace frusta {

struct SolverContact {
  int32_t object = 0;
  int32_t leaf = 0;  // -1 when a node at the tree level stands in
  int32_t body = 0;  // finger segment f * 3 + s, or kPalmBody
  int32_t part = 0;  // the palm sphere on the palm body
  double distance = 0.0;  // exact gap, >= -penetration_tolerance
  vec3 hand_point{0.0};
  vec3 object_point{0.0};
  vec3 normal{0.0};  // unit, from the object sphere towards the hand
};

struct StepStats {
  int32_t substeps = 0;
  int32_t candidates = 0;        // the most in one sub-step's set (CandidateSet::need)
  int32_t tree_nodes_visited = 0;
  int32_t iterations = 0;        // re-linearisations over every stage
  int32_t qp_iterations = 0;
  int32_t finger_solves = 0;     // finger stages run (fingers with candidates), summed
  int32_t palm_solves = 0;
  bool depenetrated = false;     // this step placed a hand that started inside
  bool lagging = false;          // the sub-step cap or the deadline stopped the hand short
  bool rate_limited = false;     // the continuity bound (follow_factor) stopped it short
  bool infeasible = false;       // some QP could not meet every row; the hand stayed safe
  bool resting = false;          // nothing to solve: the last step's hand, as it was
  // bit f: finger f began the step at rest (the last step left it where it found it,
  // aimed where it still is): it is solved again only if the palm moves
  uint32_t resting_fingers = 0;
};

// The haptic hand as the solver aims at it: rotation normalised and angles clamped to the
// model's limits, so that where nothing is touched both hands coincide and a glove
// reading past a joint limit makes no force. HandSolver::target_pose() is this for the
// state its last step took; here for callers with a state and no solver (tests,
// benchmarks). `haptic` must pass check_hand_state.
void haptic_hand_pose(const HandModel& model, const HandState& haptic, HandPose& pose);

class HandSolver {
 public:
  HandSolver(const HandModel& model, const SolverParams& params);

  // Check a parameter set against a hand; the thread's error names the field.
  static frusta_result check_params(const SolverParams& params, const HandModel& model);

  using Clock = std::chrono::steady_clock;

  // One step towards `haptic`, which must pass check_hand_state (its entry point
  // checked it). A hand that starts inside objects with no free placement near returns
  // an error and stays unplaced. Objects stay put during a step. The step budget: at
  // most max_substeps sub-steps, and none started that its recent sub-steps' cost says
  // would end after `deadline` (at least one always runs): a hand caught in a tangle of
  // contacts then lags (stats->lagging) instead of stalling a real-time thread, its last
  // sub-step sliding along what it touches so that it keeps its contacts. `finder`
  // (null: look at every object), a broad phase over `objects`: each sub-step looks only
  // at the objects it finds near the hand, with the same result. `objects_as_before`:
  // the caller vouches that `objects` is the last step's list unchanged (every tree and
  // pose, in order): the first detection copies the last step's candidates of the bodies
  // that have not moved since, which a walk would find again (a hand held still in a
  // still scene walks no tree), and a hand that the last step left where it found it,
  // aimed where it is still aimed, is not solved again (stats->resting).
  frusta_result step(const HandState& haptic, const SolverObject* objects, int32_t object_count,
                     StepStats* stats, Clock::time_point deadline = Clock::time_point::max(),
                     const ObjectFinder* finder = nullptr, bool objects_as_before = false);

  // Whether the graphic hand now sinks into `object` (past the penetration tolerance), as
  // the solver sees it (its level of detail). False before the first step.
  bool overlaps(const SolverObject& object);

  // Forget the graphic hand: the next step starts it afresh from the haptic hand.
  void reset() {
    started_ = false;
    finger_rest_.fill(false);
    reported_ = false;
    placement_ = PlacementSearch{};
  }

  bool started() const { return started_; }
  const HandState& graphic() const { return graphic_; }
  const HandPose& graphic_pose() const { return pose_; }
  // haptic_hand_pose of the last successful step's input: the forces' haptic hand, worked
  // out once here
  const HandPose& target_pose() const { return target_pose_; }
  // by body, then object, leaf and palm sphere, whatever the detection's history
  const std::vector<SolverContact>& contacts() const { return contacts_; }
  const HandModel& model() const { return model_; }
  const SolverParams& params() const { return params_; }

 private:
  // One sub-step, moving no point further than `budget` (metres, less what it moved);
  // true when every part reached its own target (or stopped against objects) without
  // hitting a motion cap. The step's `last` one slides where it is cut short; each looks
  // only the contact distance from a finger settled on a palm that will not move in it.
  bool substep(const HandState& target, const SolverObject* objects, int32_t object_count,
               bool last, StepStats& stats, double& budget, bool& moved);
  // A stage built by make(slide) solved on the graphic hand; where `budget_binds` and the
  // stage was cut short, solved again sliding from where it started (slid is set).
  template <class MakeStage>
  StageStats solve_within_budget(MakeStage make, bool budget_binds, bool& slid);
  void report_contacts();
  // where the trees' walks stop: the leaves, or the level of detail the params ask
  TreeCut tree_cut() const { return TreeCut(params_.tree_level, params_.lod_error); }
  // The bodies (bit b: body b) where the last report found them, among the same objects:
  // their contacts, and so how deep they sink, are that report's.
  uint32_t bodies_as_reported() const {
    return reported_ ? bodies_unmoved(reported_pose_, pose_) : 0u;
  }
  // report_contacts for one body: its candidates within `within` of it (by `view`), each
  // measured by `measure`
  template <class View, class Measure>
  void report_body(int body, const View& view, double within, Measure measure);

  HandModel model_;
  SolverParams params_;
  HandReach reach_;
  bool started_ = false;
  // a hand that starts inside objects: the search for its placement, which may take
  // several steps' budgets, and the haptic hand it places
  PlacementSearch placement_;
  HandState placing_;
  HandState graphic_;
  HandPose pose_;
  HandPose target_pose_;
  HandState last_target_;      // the last step's target: how far the haptic hand moves
  double unfinished_ = 0.0;    // motion allowed but not made for the deadline, metres
  double recent_move_ = 0.0;   // how far the haptic hand moves a step, lately (follow_decay)
  Clock::duration substep_cost_{0};  // the longest sub-step of steps with a deadline, fading
  // this step's deadline, aimed short of the caller's by overrun_: how far past its aim
  // a step that ran to it ended (the work after the last check), the longest lately
  Clock::time_point deadline_ = Clock::time_point::max();
  Clock::duration overrun_{0};
  PalmHeading heading_;        // this step's: the graphic palm does not go back against it
  CandidateSet candidates_;  // this pose's detection, kept in place by cache_ between steps
  CandidateCache cache_;  // the trees' walks, kept while the objects are as before
  // candidates_ holds this pose's detection (false once it served as scratch)
  bool detected_ = false;
  // the last step ended where it began (within kStandstill), neither lagging nor held
  // back by its bound: the same inputs would leave the hand there again
  bool resting_ = false;
  const ObjectFinder* finder_ = nullptr;  // this step's
  // What the finder found in found_box_, in index order: a box a little larger than a
  // sub-step asks for, whose answer later sub-steps and steps take while their box lies
  // inside it and the objects are as before. -1: nothing found that still holds.
  std::vector<int32_t> near_;
  Aabb found_box_;
  int32_t found_count_ = -1;
  std::array<bool, FRUSTA_FINGER_COUNT> settled_{};  // per sub-step: reached or stopped
  // per finger, as resting_ for the hand: the last step left it where it found it
  std::array<bool, FRUSTA_FINGER_COUNT> finger_rest_{};
  std::vector<QpRow> rows_;
  // what each part's last QP ended with active: the next one's warm start (QpHints)
  std::array<QpHints, FRUSTA_FINGER_COUNT> finger_hints_{};
  QpHints palm_hints_;
  StagePoses stage_poses_;  // the stages' trials, one stage at a time
  std::vector<SolverContact> contacts_;
  // the report before (report_contacts' scratch), where the hand stood for the last
  // report and how far each body looked; reported_: among the objects as they still are
  // (bodies_as_reported)
  std::vector<SolverContact> last_contacts_;
  HandPose reported_pose_;
  std::array<double, kBodyCount> reported_within_{};
  bool reported_ = false;
};

}  // namespace frusta
