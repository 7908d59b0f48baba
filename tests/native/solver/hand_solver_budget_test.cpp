// SPDX-License-Identifier: MIT
// Issue 20, Build 3: where the step budget binds (StepStats::lagging), the graphic hand
// stays out of the objects and the forces stay continuous by the edge slides' bound: a
// patch's push changes a step by at most the contact stiffness times its body's haptic
// move plus 0.05 N. The budget is the sub-step cap here (deterministic); a deadline ends
// a step the same way (HandSolver::step). The edge slides under the same cap are in
// hand_solver_edges_test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "forces/contact_forces.h"
#include "forces/force_params.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/hand_scenarios.h"
#include "solver/hand_solver.h"

namespace frusta {
namespace {

constexpr double kForceSlack = 0.05;         // newtons, the edge slides' bound
constexpr double kMaxPenetration = 0.05e-3;  // metres, the solver's floor

TEST(HandSolverBudget, ADeepGraspOfTenThousandLeavesPushesContinuouslyWhereTheBudgetBinds) {
  const scenes::HandScenario s = scenes::ball_grasp(scenes::ball_shell(10000, 0.04));
  SolverParams params;
  params.max_substeps = 1;  // the grasp closes faster than one sub-step a step can follow
  const HandModel model = make_hand_model(default_hand_def());
  HandSolver solver(model, params);
  ContactForces forces;
  const int32_t count = static_cast<int32_t>(s.objects.size());
  std::array<vec3, kBodyCount> before{};
  HandPose haptic_before;
  int lagged = 0, held_back = 0;
  double worst = -INFINITY, deepest = 0.0;
  int worst_step = -1, worst_body = -1;
  const int32_t steps = s.steps + 100;
  for (int32_t t = 0; t < steps; ++t) {
    StepStats stats;
    ASSERT_EQ(solver.step(t < s.steps ? s.haptic(t) : s.held, s.objects.data(), count, &stats), FRUSTA_OK);
    ContactForceStats force_stats;
    const std::vector<SolverContact>& contacts = solver.contacts();
    forces.update(solver.graphic_pose(), solver.target_pose(), contacts.data(),
                  static_cast<int32_t>(contacts.size()), s.objects.data(), count, nullptr, &force_stats,
                  stats.lagging);
    lagged += stats.lagging ? 1 : 0;
    held_back += force_stats.held_back > 0 ? 1 : 0;
    std::array<vec3, kBodyCount> push{};
    for (const ContactForce& f : forces.forces()) push[static_cast<size_t>(f.body)] += f.normal_force;
    // where the budget binds (and until the pushes are their own again); elsewhere a
    // deep grasp's pushes are the solver's own (the edge slides bound those)
    if (t > 0 && (stats.lagging || force_stats.held_back > 0))
      for (int body = 0; body < kBodyCount; ++body) {
        const double move = scenes::body_move(model, haptic_before, solver.target_pose(), body);
        const double change = glm::length(push[static_cast<size_t>(body)]) - glm::length(before[static_cast<size_t>(body)]);
        const double excess = std::fabs(change) - (kDefaultContactStiffness * move + kForceSlack);
        if (excess > worst) {
          worst = excess;
          worst_step = t;
          worst_body = body;
        }
      }
    if (t % 10 == 0 || t == steps - 1)
      deepest = std::max(deepest, scenes::deepest_penetration(model, solver.graphic_pose(), s.objects));
    before = push;
    haptic_before = solver.target_pose();
  }
  EXPECT_GT(lagged, 20) << "the budget is meant to bind";
  EXPECT_GT(held_back, 0) << "and the lag to hold some push back";
  EXPECT_LE(worst, 0.0) << "body " << worst_body << "'s push changed " << worst << " N too much in step " << worst_step;
  EXPECT_LE(deepest, kMaxPenetration);
}

// A glove that jumps from open to a curled index in one sample, its step cut short: the
// finger closes the 2 mm gap to the box in its first three sub-steps and touches it, so the
// step's forces (and the glove's brake) answer the press at once. A finger stage aimed
// past its cap stepped straight towards its target cut short, along rows linearised for
// that far target: the index slid sideways (its first joint bent back) and touched the
// box only in the fifth sub-step, a period late when the budget ended the step before.
TEST(HandSolverBudget, AFingerJumpingIntoABoxTouchesItWithinTheStepsFirstSubSteps) {
  const HandModel model = make_hand_model(default_hand_def());
  const auto box = scenes::test_box("press_box");
  SolverObject object{&box->tree, {}};
  object.pose.position =
      scenes::index_press_box_centre(model, 0.5 * scenes::test_box_spec("press_box").size.x, 0.002);
  HandState open = scenes::open_hand(), curled = open;
  scenes::set_flexion(curled, FRUSTA_FINGER_INDEX, 0.84, 0.94, 0.73);  // 0.6 of a fist
  for (const int32_t substeps : {3, 4}) {
    SolverParams params;
    params.max_substeps = substeps;
    HandSolver solver(model, params);
    ASSERT_EQ(solver.step(open, &object, 1, nullptr), FRUSTA_OK);
    StepStats stats;
    ASSERT_EQ(solver.step(curled, &object, 1, &stats), FRUSTA_OK);
    EXPECT_TRUE(stats.lagging) << substeps;
    EXPECT_FALSE(solver.contacts().empty()) << "after " << substeps << " sub-steps";
    EXPECT_LE(scenes::deepest_penetration(model, solver.graphic_pose(), {object}), kMaxPenetration);
  }
}

}  // namespace
}  // namespace frusta
