// SPDX-License-Identifier: MIT
// A linearisation makes only the rows of spheres a step within a radius can reach
// (stage.h, kRowRadius). Where its step stays within that radius it must be the step
// every row makes: the spheres left out lie further than that step moves the hand, so
// their rows cannot bind. Where it goes further and the stage keeps it (it ends clear of
// every candidate), it must be no further from its target than the step every row makes:
// fewer rows can only let it nearer. Checked on the poses the solver passes through in
// every acceptance scenario and the deep grasp, against the same stage linearised whole;
// and a trial of a step within its radius, whose gap the stage takes from its rows'
// spheres alone, against every candidate's.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"
#include "solver/finger_stage.h"
#include "solver/hand_solver.h"
#include "solver/palm_stage.h"

namespace frusta {
namespace {

struct Tally {
  int within = 0;  // restricted steps that stayed within their radius
  int fewer = 0;   // ... with fewer rows than the whole linearisation
  int kept = 0;    // restricted steps beyond their radius, clear of every candidate
};

// Solve `make()`'s first linearisation whole, then within radii around its step; a step
// within its radius must equal the whole one, and check_step(stage, d) holds for it; one
// beyond it that ends clear must be no further from its target than the whole one, and
// check_kept(stage, d, gap) holds for the gap the stage measured it by.
template <class MakeStage, class CheckStep, class CheckKept>
void compare_radii(MakeStage make, CheckStep check_step, CheckKept check_kept,
                   std::vector<QpRow>& rows, Tally& tally, const char* what, int step) {
  // (every linearisation of a stage at one estimate makes the same target and weights)
  double target[kMaxQpVariables] = {}, weights[kMaxQpVariables] = {};
  auto solve = [&](auto& stage, double radius, double* d, int32_t& count, bool& optimal) {
    rows.resize(static_cast<size_t>(stage.row_capacity() + kMaxLazyRows));
    count = stage.linearise(rows.data(), target, weights, radius);
    optimal = solve_projection_qp(stage.dofs(), weights, target, rows.data(), count, 64, d,
                                  lazy_rows(stage))
                  .status == QpStatus::kOptimal;
    return stage.step_motion(d);
  };
  auto objective = [&](const double* d) {  // the QPs': half the weighted square to the target
    double sum = 0.0;
    for (int j = 0; j < kMaxQpVariables; ++j) sum += 0.5 * weights[j] * (d[j] - target[j]) * (d[j] - target[j]);
    return sum;
  };
  double whole[kMaxQpVariables] = {};
  int32_t whole_rows = 0;
  bool whole_optimal = false;
  auto whole_stage = make();
  const double motion = solve(whole_stage, INFINITY, whole, whole_rows, whole_optimal);
  if (!(motion > 0.0)) return;
  for (double share : {0.05, 0.25, 0.5, 1.0, 2.0}) {
    const double radius = share * motion;
    double d[kMaxQpVariables] = {};
    int32_t count = 0;
    bool optimal = false;
    auto stage = make();
    if (solve(stage, radius, d, count, optimal) > radius) {
      // solve_stage keeps it where it ends clear of every candidate, else makes it again
      const double gap = stage.try_step_anywhere(d);
      check_kept(stage, d, gap);
      if (!optimal || !whole_optimal || !(gap >= stage.floor())) continue;
      ++tally.kept;
      ASSERT_LE(objective(d), objective(whole) * (1.0 + 1e-9) + 1e-18)
          << what << " at step " << step << ", radius " << share << " of the step, " << count
          << " of " << whole_rows << " rows";
      continue;
    }
    ++tally.within;
    tally.fewer += count < whole_rows;
    for (int j = 0; j < kMaxQpVariables; ++j)
      ASSERT_NEAR(d[j], whole[j], 1e-9)
          << what << " at step " << step << ", radius " << share << " of the step, " << count
          << " of " << whole_rows << " rows";
    check_step(stage, d);
  }
}

void check_scenario(const scenes::HandScenario& s, Tally& fingers, Tally& palm, int& trials,
                    int& touching) {
  const HandModel model = make_hand_model(default_hand_def());
  const HandReach reach = hand_reach(model);
  const SolverParams params;
  HandSolver solver(model, params);
  CandidateSet candidates;
  std::vector<QpRow> rows;
  const auto object_count = static_cast<int32_t>(s.objects.size());
  for (int32_t t = 0; t + 1 < s.steps; t += 3) {
    ASSERT_EQ(solver.step(s.haptic(t), s.objects.data(), object_count, nullptr), FRUSTA_OK);
    const HandState target = s.haptic(t + 1);
    detect_candidates(model, reach, solver.graphic_pose(), s.objects.data(), object_count,
                      DetectionMargins(params.prediction_margin),
                      TreeCut(params.tree_level, params.lod_error), candidates);
    const StageInputs inputs{model, reach, params, candidates};
    // what a stage updates in place, as the solver left it for each solve
    HandState state;
    HandPose pose;
    QpHints hints;
    StagePoses poses;
    auto reset = [&] {
      state = solver.graphic();
      pose = solver.graphic_pose();
      hints = QpHints{};
    };
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      if (candidates.finger_count(f) == 0) continue;
      FingerAngles to;
      std::copy_n(target.angles.begin() + f * FRUSTA_JOINTS_PER_FINGER, to.size(), to.begin());
      // the gap of every candidate at the trial `part` of the step d
      auto every_candidates_gap = [&](FingerStage& stage, const double* d, double part) {
        const FingerModel& finger = model.fingers[f];
        HandState trial = solver.graphic();
        for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
          double& a = trial.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)];
          a = std::clamp(a + part * d[j], finger.joint_min[j], finger.joint_max[j]);
        }
        HandPose trial_pose;
        forward_kinematics(model, trial, trial_pose);
        return stage.clearance(trial_pose);
      };
      // a trial of the step has the gap every candidate gives it, from its rows' alone
      auto trials_see_every_candidate = [&](FingerStage& stage, const double* d) {
        for (double part : {1.0, 0.5, 0.125}) {
          const double gap = stage.try_step(d, part);
          if (gap == -INFINITY) continue;  // beyond the cap: refused before any gap
          ASSERT_EQ(gap, every_candidates_gap(stage, d, part))
              << s.name << " at step " << t << ", finger " << f;
          ++trials;
          touching += gap < 0.0;
        }
      };
      // and one beyond its radius is measured by every candidate too
      auto kept_by_every_candidate = [&](FingerStage& stage, const double* d, double gap) {
        if (gap == -INFINITY) return;  // beyond the cap
        ASSERT_EQ(gap, every_candidates_gap(stage, d, 1.0))
            << s.name << " at step " << t << ", finger " << f << ", a step beyond its radius";
      };
      for (FingerBound bound : {FingerBound::kHalve, FingerBound::kTrust}) {
        compare_radii(
            [&] {
              reset();
              return FingerStage(inputs, f, to, {params.prediction_margin, params.prediction_margin}, bound, hints, poses, state, pose,
                                 finger_clearance(model, pose, candidates, f));
            },
            trials_see_every_candidate, kept_by_every_candidate, rows, fingers, s.name.c_str(), t);
      }
    }
    if (candidates.size() == 0) continue;
    const PalmPlacement to{target.palm_position, glm::normalize(target.palm_rotation)};
    for (bool slide : {false, true}) {
      compare_radii(
          [&] {
            reset();
            double start_gap = 0.0;
            for (int body = 0; body < kBodyCount; ++body)
              start_gap = std::min(start_gap, body_clearance(model, pose, candidates, body));
            return PalmStage(inputs, to, 0.5 * params.prediction_margin, PalmHeading{}, slide,
                             hints, poses, state, pose, start_gap);
          },
          [](PalmStage&, const double*) {}, [](PalmStage&, const double*, double) {}, rows, palm,
          s.name.c_str(), t);
    }
  }
}

TEST(StageRows, AStepIsEveryRowsStepWithinItsRadiusAndNoFurtherFromItsTargetBeyondIt) {
  Tally fingers, palm;
  int trials = 0, touching = 0;
  for (const std::string& name : scenes::hand_scenario_names())
    check_scenario(scenes::make_hand_scenario(name), fingers, palm, trials, touching);
  check_scenario(scenes::ball_grasp(scenes::ball_shell(3000, 0.04)), fingers, palm, trials,
                 touching);
  // the comparisons that test something: rows left out, and a step the same without them
  EXPECT_GT(fingers.fewer, 1000) << fingers.within << " finger steps within their radius";
  EXPECT_GT(fingers.kept, 1000) << "finger steps kept beyond their radius";
  EXPECT_GT(palm.kept, 100) << "palm steps kept beyond their radius";
  EXPECT_GT(palm.fewer, 100) << palm.within << " palm steps within their radius";
  EXPECT_GT(touching, 100) << trials << " trials";
}

}  // namespace
}  // namespace frusta
