// SPDX-License-Identifier: MIT
// The graphic hand on the scripted haptic trajectories of the acceptance list
// (tests/scenes/hand_scenarios). Every scenario checks the floor: the graphic hand never
// sinks more than 0.05 mm into the exact leaf-sphere set, held still in contact it
// neither drifts nor rocks, and bad input leaves it as it was. Each then checks what
// the scenario is about.
#include "solver/hand_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/random_scenes.h"
#include "solver/depenetration.h"
#include "solver/detection.h"
#include "solver/finger_stage.h"
#include "solver/palm_stage.h"
#include "scenario_run.h"
#include "scene_finder.h"

namespace frusta {
namespace {

using scenes::HandScenario;
using scenes::make_hand_scenario;

constexpr double kMaxPenetration = 0.05e-3;  // the acceptance floor, metres
constexpr double kMaxDrift = 1e-6;           // rad (and m) over 1,000 held steps
constexpr int kHoldSteps = 1000;

HandModel default_model() { return make_hand_model(default_hand_def()); }

// Run the script; check the floor throughout.
HandSolver run_scripted(const HandScenario& s, testing::RunLog& log) {
  HandSolver solver(default_model(), SolverParams{});
  log = testing::run(solver, s);
  EXPECT_EQ(log.steps, s.steps);
  EXPECT_LE(log.max_penetration, kMaxPenetration) << s.name;
  return solver;
}

// The floor's second half: hold, then bad input, which the one rule for hand inputs
// (check_hand_state, at every entry point) refuses before any solver sees it.
void expect_holds_and_rejects_bad_input(HandSolver& solver, const HandScenario& s, testing::RunLog& log) {
  const double drift = testing::hold_drift(solver, s, kHoldSteps, log);
  EXPECT_LT(drift, kMaxDrift) << s.name << ": the graphic hand moved while the haptic hand was held still";
  EXPECT_LE(log.max_penetration, kMaxPenetration) << s.name;
  const HandState before = solver.graphic();
  const int32_t count = static_cast<int32_t>(s.objects.size());
  HandState bad = s.held;
  bad.angles[6] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("haptic.angles[6]"), std::string::npos);
  bad = s.held;
  bad.palm_position.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_ERROR_NOT_FINITE);
  bad = s.held;
  bad.palm_position.x = 1e9;  // a glove reading a million kilometres away is garbage
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_ERROR_OUT_OF_RANGE);
  bad = s.held;
  bad.palm_rotation = glm::dquat(0, 0, 0, 0);
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_ERROR_OUT_OF_RANGE);
  bad = s.held;
  bad.angles[0] = std::nextafter(kMaxJointAngle, 100.0);
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_ERROR_OUT_OF_RANGE);
  // the largest accepted angle is clamped into the limits and solved like any other
  bad.angles[0] = kMaxJointAngle;
  EXPECT_EQ(check_hand_state(bad, "haptic"), FRUSTA_OK);
  EXPECT_EQ(solver.step(bad, s.objects.data(), count, nullptr), FRUSTA_OK);
  EXPECT_LE(solver.graphic().angles[0], solver.model().fingers[0].joint_max[0])
      << "clamped into the limits, not taken as is";
  EXPECT_EQ(check_hand_state(s.held, "haptic"), FRUSTA_OK);
  (void)before;
}

bool touches(const HandSolver& solver, int finger) {
  for (const SolverContact& c : solver.contacts())
    if (c.body != kPalmBody && c.body / FRUSTA_SEGMENTS_PER_FINGER == finger) return true;
  return false;
}

TEST(HandSolver, InFreeSpaceTheGraphicHandIsTheHapticHand) {
  HandScenario s;
  s.add(scenes::sample_tree("ball"), {vec3(1.0, 0.0, 0.0), glm::dmat3(1.0)});  // a metre away
  HandSolver solver(default_model(), SolverParams{});
  for (int t = 0; t < 300; ++t) {
    HandState h = scenes::open_hand(vec3(0.001 * t, 0.0, 0.0005 * t), scenes::about(vec3(1, 2, 3), 0.01 * t));
    for (size_t j = 0; j < h.angles.size(); ++j) h.angles[j] = 0.8 * std::sin(0.05 * t + static_cast<double>(j));
    StepStats stats;
    ASSERT_EQ(solver.step(h, s.objects.data(), 1, &stats), FRUSTA_OK);
    HandState clamped = h;
    clamp_to_limits(solver.model(), clamped);
    ASSERT_LT(testing::state_change(clamped, solver.graphic()), 1e-9) << "step " << t;
    EXPECT_EQ(stats.finger_solves + stats.palm_solves, 0) << "nothing near: nothing to solve";
    EXPECT_TRUE(solver.contacts().empty());
  }
}

// HandSolverScenario: the acceptance list's scripted scenarios (scenes/hand_scenarios.h),
// every step checked against the exact reference
TEST(HandSolverScenario, FingertipPressedIntoABoxFaceStopsOnIt) {
  const HandScenario s = make_hand_scenario("box_press");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  EXPECT_TRUE(touches(solver, 1));
  EXPECT_LT(solver.graphic().angles[5], s.held.angles[5] - 0.1) << "the index stopped short";
  for (const SolverContact& c : solver.contacts()) EXPECT_EQ(c.body / 3, 1) << "only the index touches";
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolverScenario, DeepGraspOfABallLeavesEveryFingerOnItsSurface) {
  const HandScenario s = make_hand_scenario("ball_grasp");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  for (int f = 1; f < 5; ++f) EXPECT_TRUE(touches(solver, f)) << "finger " << f << " wraps the ball";
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolverScenario, FingertipSlidesAlongASurfaceWithoutSinking) {
  const HandScenario s = make_hand_scenario("slide");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  // the palm carries the index rigidly over the leaves' bumps, so it may lag a little
  EXPECT_NEAR(solver.graphic().palm_position.x, 0.03, 1e-4) << "the palm slid (nearly) all the way";
  EXPECT_TRUE(touches(solver, 1)) << "still pressing at the end";
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolverScenario, ThumbAndIndexPinchAThinPlate) {
  const HandScenario s = make_hand_scenario("plate_pinch");
  HandSolver probe(default_model(), SolverParams{});
  StepStats first;
  ASSERT_EQ(probe.step(s.haptic(0), s.objects.data(), 1, &first), FRUSTA_OK);
  ASSERT_FALSE(first.depenetrated) << "the scene must start free for the test to mean anything";
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  EXPECT_TRUE(touches(solver, 0));
  EXPECT_TRUE(touches(solver, 1));
  const HandPose& g = solver.graphic_pose();
  EXPECT_LT(glm::dot(g.fingers[0].joint[3] - s.anchor, s.axis), 0.0) << "thumb stays on its side";
  EXPECT_GT(glm::dot(g.fingers[1].joint[3] - s.anchor, s.axis), 0.0) << "index stays on its side";
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolverScenario, FingersPressIntoAConcaveBowl) {
  const HandScenario s = make_hand_scenario("bowl_press");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  EXPECT_FALSE(solver.contacts().empty());
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolverScenario, HapticHandTeleportingThroughAPlateLeavesTheGraphicHandOnTop) {
  const HandScenario s = make_hand_scenario("plate_teleport");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  // every joint and palm sphere over the plate's footprint stayed above it
  const HandPose& g = solver.graphic_pose();
  auto over_plate = [&](const vec3& p) { return std::fabs(p.x - s.anchor.x) < 0.06 && std::fabs(p.y - s.anchor.y) < 0.04; };
  int over = 0;
  for (int k = 0; k < static_cast<int>(solver.model().palm_spheres.size()); ++k) {
    const vec3 c = palm_sphere(solver.model(), g, k).center;
    if (!over_plate(c)) continue;
    EXPECT_GT(c.z, s.anchor.z) << "palm sphere " << k;
    ++over;
  }
  for (int f = 0; f < 5; ++f)
    for (const vec3& j : g.fingers[f].joint) {
      if (!over_plate(j)) continue;
      EXPECT_GT(j.z, s.anchor.z) << "finger " << f;
      ++over;
    }
  EXPECT_GT(over, 20) << "most of the hand is over the plate";
  EXPECT_FALSE(solver.contacts().empty()) << "resting on the plate";
  expect_holds_and_rejects_bad_input(solver, s, log);
}

TEST(HandSolver, APassedDeadlineStopsAfterOneSubStepAndTheHandLagsSafely) {
  // the teleport needs 32 sub-steps; with its deadline gone each step takes one, the
  // hand lags (and says so) but never sinks, and catches up over the next steps
  const HandScenario s = make_hand_scenario("plate_teleport");
  HandSolver solver(make_hand_model(default_hand_def()), SolverParams{});
  const HandSolver::Clock::time_point gone = HandSolver::Clock::now();
  int lagged = 0;
  for (int32_t t = 0; t < s.steps + 200; ++t) {
    StepStats stats;
    ASSERT_EQ(solver.step(t < s.steps ? s.haptic(t) : s.held, s.objects.data(),
                          static_cast<int32_t>(s.objects.size()), &stats, gone),
              FRUSTA_OK);
    EXPECT_EQ(stats.substeps, 1) << "step " << t;
    // a stage held back by its budget slides, one linearisation past the deadline (its
    // straight solve's two before it), not the six a sliding stage may take
    EXPECT_LE(stats.iterations, 3) << "step " << t;
    lagged += stats.lagging ? 1 : 0;
    ASSERT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), 1e-5)
        << "step " << t;
  }
  EXPECT_GT(lagged, 10) << "the jump took several steps to follow";
  EXPECT_FALSE(solver.contacts().empty()) << "and the hand ends resting on the plate";
}

// The search for a hand that starts inside takes its steps' budgets; the step it ends in
// has none left for a sub-step, and reports no contacts of the search's trials.
TEST(HandSolver, APlacementThatTookTheStepsBudgetLeavesItsSubStepsToTheNext) {
  const HandScenario s = make_hand_scenario("start_inside");
  HandSolver solver(make_hand_model(default_hand_def()), SolverParams{});
  const HandSolver::Clock::time_point gone = HandSolver::Clock::now();
  int32_t t = 0;
  StepStats stats;
  for (; t < 1000 && !solver.started(); ++t)
    ASSERT_EQ(solver.step(s.haptic(t), s.objects.data(), 1, &stats, gone), FRUSTA_OK);
  ASSERT_TRUE(solver.started());
  EXPECT_GT(t, 1) << "one trial a step: the search took several";
  EXPECT_TRUE(stats.depenetrated);
  EXPECT_EQ(stats.substeps, 0);
  EXPECT_TRUE(stats.lagging);
  EXPECT_TRUE(solver.contacts().empty());
  EXPECT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), kMaxPenetration);
  ASSERT_EQ(solver.step(s.haptic(t), s.objects.data(), 1, &stats, gone), FRUSTA_OK);
  EXPECT_EQ(stats.substeps, 1) << "the next step goes on as ever";
}

TEST(HandSolverScenario, HapticHandStartingInsideAnObjectIsPlacedOutside) {
  const HandScenario s = make_hand_scenario("start_inside");
  HandSolver solver(default_model(), SolverParams{});
  StepStats first;
  ASSERT_EQ(solver.step(s.haptic(0), s.objects.data(), 1, &first), FRUSTA_OK);
  EXPECT_TRUE(first.depenetrated);
  EXPECT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), kMaxPenetration);
  EXPECT_GT(std::fabs(solver.graphic().palm_position.z), 0.08) << "out through the nearest faces (z, 8 cm)";
  testing::RunLog log = testing::run(solver, s);
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  expect_holds_and_rejects_bad_input(solver, s, log);
}

// On a level of detail the nodes that stand in for the leaves are the object: a hand
// that starts inside is placed clear of them. Before, the placement searched clear of
// the leaves alone and the first step's contacts sank up to 18 mm into the nodes, which
// the steps after pushed the hand out of (a random scene found it).
TEST(HandSolverScenario, AHandStartingInsideOnALevelOfDetailIsPlacedClearOfItsNodes) {
  const HandScenario s = make_hand_scenario("start_inside");
  for (const TreeCut cut : {TreeCut(2), TreeCut(-1, 0.004)}) {
    SolverParams params;
    params.tree_level = cut.max_level;
    params.lod_error = cut.max_error;
    HandSolver solver(default_model(), params);
    StepStats first;
    ASSERT_EQ(solver.step(s.haptic(0), s.objects.data(), 1, &first), FRUSTA_OK);
    EXPECT_TRUE(first.depenetrated);
    EXPECT_FALSE(first.lagging);
    EXPECT_FALSE(solver.overlaps(s.objects[0]));
    // every pair within the contact distance, of the nodes the cut stops at
    CandidateSet nodes;
    detect_candidates(solver.model(), hand_reach(solver.model()), solver.graphic_pose(),
                      s.objects.data(), 1, DetectionMargins(0.0), cut, nodes);
    for (int body = 0; body < kBodyCount; ++body)
      EXPECT_GE(body_clearance(solver.model(), solver.graphic_pose(), nodes, body),
                -params.penetration_tolerance)
          << "body " << body << " at level " << cut.max_level << ", error " << cut.max_error;
  }
}

// Issue 20: the placement search costs tens of trials (40 and 11.6 ms in start_inside),
// more than a step's budget. Cut at every trial by a deadline long past, it goes on over
// the next steps, the hand not placed meanwhile, and places it exactly where the whole
// search does.
TEST(HandSolverScenario, APlacementCutByTheDeadlineGoesOnOverTheNextStepsToTheSamePlace) {
  const HandScenario s = make_hand_scenario("start_inside");
  const HandModel model = default_model();
  const HandReach reach = hand_reach(model);
  CandidateSet scratch;
  HandState whole = s.haptic(0);
  PlacementSearch search;
  ASSERT_EQ(search.run(model, reach, s.objects.data(), 1, SolverParams{}.penetration_tolerance, TreeCut(), scratch,
                       PlacementSearch::Clock::time_point::max(), &whole),
            PlacementSearch::Result::kFound);
  ASSERT_FALSE(search.pending());
  // one trial a run: the same trials in the same order, the same placement to the bit
  HandState cut = s.haptic(0);
  int runs = 1;
  while (search.run(model, reach, s.objects.data(), 1, SolverParams{}.penetration_tolerance, TreeCut(), scratch,
                    PlacementSearch::Clock::time_point::min(), &cut) == PlacementSearch::Result::kPending)
    ++runs;
  EXPECT_EQ(cut.palm_position, whole.palm_position);
  EXPECT_GT(runs, 20) << "the search is meant to take many trials";

  HandSolver solver(model, SolverParams{});
  const auto gone = HandSolver::Clock::now() - std::chrono::seconds(1);
  int steps = 0;
  StepStats stats;
  do {
    ASSERT_EQ(solver.step(s.haptic(0), s.objects.data(), 1, &stats, gone), FRUSTA_OK);
    ++steps;
    if (!solver.started()) {
      EXPECT_TRUE(stats.lagging);
      EXPECT_TRUE(solver.contacts().empty());
    }
  } while (!solver.started() && steps < 10000);
  ASSERT_TRUE(solver.started());
  std::printf("placed on step %d, one trial a step\n", steps);
  EXPECT_EQ(steps, runs) << "a trial a step";
  EXPECT_TRUE(stats.depenetrated);
  // the step that placed it ran one sub-step from there: the palm's placement is the
  // whole search's, moved by that sub-step at most Delta_r
  EXPECT_LE(glm::length(solver.graphic().palm_position - whole.palm_position),
            SolverParams{}.prediction_margin);
  EXPECT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), kMaxPenetration);
}

TEST(HandSolverScenario, PalmPressedFlatOnABoxThenFingersClose) {
  const HandScenario s = make_hand_scenario("palm_then_fingers");
  testing::RunLog log;
  HandSolver solver = run_scripted(s, log);
  EXPECT_GT(solver.graphic().palm_position.z, -0.0015) << "the palm rests on the box top";
  bool palm_touches = false;
  for (const SolverContact& c : solver.contacts()) palm_touches |= c.body == kPalmBody;
  EXPECT_TRUE(palm_touches);
  expect_holds_and_rejects_bad_input(solver, s, log);
}

// The graphic pose is what the forces, contacts and the next step read: it must be the
// graphic state's kinematics exactly, though the stages pose only what they move. A
// finger stage's bisection blended the whole hand, and turned the palm by a rounding
// (a slerp between equal rotations) its finger's pose did not follow (palm_then_fingers,
// step 187).
TEST(HandSolver, TheGraphicPoseIsTheGraphicStatesKinematicsEveryStep) {
  int steps = 0;
  for (const std::string& name : scenes::hand_scenario_names()) {
    const HandScenario s = make_hand_scenario(name);
    HandSolver solver(default_model(), SolverParams{});
    for (int t = 0; t < s.steps; ++t) {
      ASSERT_EQ(solver.step(s.haptic(t), s.objects.data(), static_cast<int32_t>(s.objects.size()),
                            nullptr),
                FRUSTA_OK);
      if (!solver.started()) continue;
      HandPose fresh;
      forward_kinematics(solver.model(), solver.graphic(), fresh);
      ASSERT_EQ(bodies_unmoved(fresh, solver.graphic_pose()), (1u << kBodyCount) - 1u)
          << name << " step " << t;
      ++steps;
    }
  }
  EXPECT_GT(steps, 1000);
}

// The contacts of the solver's graphic hand, each pair within its contact distance found
// afresh (body, object, leaf, palm sphere), sorted; the solver's report the same way
// (reported_pairs). Each reported object point is checked against the one measured afresh.
using ContactPair = std::array<int32_t, 4>;
std::vector<ContactPair> fresh_contacts(const HandSolver& solver, const SolverObject* objects,
                                        int32_t count) {
  const HandModel& model = solver.model();
  const HandPose& pose = solver.graphic_pose();
  const double within = solver.params().contact_distance;
  CandidateSet fresh;
  detect_candidates(model, hand_reach(model), pose, objects, count, DetectionMargins(within),
                    TreeCut(), fresh);
  std::vector<ContactPair> expected;
  for (int body = 0; body < kBodyCount; ++body) {
    const Candidate* c = fresh.of(body);
    for (int32_t i = 0; i < fresh.count(body); ++i) {
      Proximity p;
      if (body == kPalmBody) {
        p = exact_proximity(palm_sphere(model, pose, c[i].part), c[i].world);
      } else {
        const SegmentFrame frame = make_segment_frame(finger_segment(
            model, pose, body / FRUSTA_SEGMENTS_PER_FINGER, body % FRUSTA_SEGMENTS_PER_FINGER));
        p = exact_proximity(frame, c[i].world);
      }
      if (!(p.distance <= within)) continue;
      expected.push_back({body, c[i].object, c[i].leaf, c[i].part});
      const auto reported = std::find_if(solver.contacts().begin(), solver.contacts().end(),
                                         [&](const SolverContact& r) {
                                           return r.body == body && r.object == c[i].object &&
                                                  r.leaf == c[i].leaf && r.part == c[i].part;
                                         });
      if (reported != solver.contacts().end()) {
        EXPECT_LE(glm::length(reported->object_point - p.object_point), 1e-12) << "body " << body;
      }
    }
  }
  std::sort(expected.begin(), expected.end());
  return expected;
}

std::vector<ContactPair> reported_pairs(const HandSolver& solver) {
  std::vector<ContactPair> reported;
  for (const SolverContact& c : solver.contacts())
    reported.push_back({c.body, c.object, c.leaf, c.part});
  std::sort(reported.begin(), reported.end());
  return reported;
}

// The contacts a step reports are every pair within the contact distance of the hand
// where it ended, as a fresh detection there finds them: whatever the sub-steps kept of
// what they detected (a finger that settled in an earlier sub-step is not looked for
// again) must hold them all. Every scenario's steps, the scene vouched for as still
// (objects_as_before) or not: a body that has not moved since the last report reports
// its contacts again then.
TEST(HandSolver, TheContactsAStepReportsAreEveryPairWithinTheContactDistance) {
  const SolverParams params;
  int contacts = 0;
  for (bool vouched : {false, true}) {
    for (const std::string& name : scenes::hand_scenario_names()) {
      const HandScenario s = make_hand_scenario(name);
      HandSolver solver(default_model(), params);
      const auto count = static_cast<int32_t>(s.objects.size());
      for (int t = 0; t < s.steps + 20; ++t) {
        ASSERT_EQ(solver.step(t < s.steps ? s.haptic(t) : s.held, s.objects.data(), count, nullptr,
                              HandSolver::Clock::time_point::max(), nullptr, vouched && t > 0),
                  FRUSTA_OK);
        if (!solver.started()) continue;
        const std::vector<ContactPair> reported = reported_pairs(solver);
        ASSERT_EQ(reported, fresh_contacts(solver, s.objects.data(), count))
            << name << " step " << t << (vouched ? " vouched" : "");
        contacts += static_cast<int>(reported.size());
      }
    }
  }
  EXPECT_GT(contacts, 20000);
}

// A still finger reports its contacts again only among the objects as they were: a box
// slides 2.3 mm along its face under an index finger that hovers off it (the box 2.2 mm
// from the open fingertip, within a contact distance of 1.9 mm, the hand aimed where it
// is), the caller saying the objects changed, and the finger, which does not move, is
// near other leaves at other points.
TEST(HandSolver, AStillBodyNearAMovedObjectMeasuresItsContactsAgain) {
  const HandModel model = default_model();
  const auto box = scenes::test_box("press_box");
  SolverObject object{&box->tree, {}};
  object.pose.position = scenes::index_press_box_centre(
      model, 0.5 * scenes::test_box_spec("press_box").size.x, 0.0022);
  SolverParams params;
  params.contact_distance = 0.0019;
  HandSolver solver(model, params);
  StepStats stats;
  ASSERT_EQ(solver.step(scenes::open_hand(), &object, 1, &stats), FRUSTA_OK);
  const HandState open = solver.graphic();  // aimed where it is
  for (int t = 0; t < 3; ++t)
    ASSERT_EQ(
        solver.step(open, &object, 1, &stats, HandSolver::Clock::time_point::max(), nullptr, true),
        FRUSTA_OK);
  ASSERT_TRUE(stats.resting);
  const std::vector<ContactPair> before = reported_pairs(solver);
  ASSERT_FALSE(before.empty());
  const HandState still = solver.graphic();
  // along the face the fingertip hovers over: an axis other than the one towards it
  const vec3 toward =
      object.pose.position - solver.graphic_pose().fingers[FRUSTA_FINGER_INDEX].joint[3];
  const int normal = std::fabs(toward.x) >= std::max(std::fabs(toward.y), std::fabs(toward.z)) ? 0
                     : std::fabs(toward.y) >= std::fabs(toward.z)                              ? 1
                                                                                               : 2;
  object.pose.position[(normal + 1) % 3] += 0.0023;
  ASSERT_EQ(
      solver.step(open, &object, 1, &stats, HandSolver::Clock::time_point::max(), nullptr, false),
      FRUSTA_OK);
  ASSERT_EQ(testing::state_change(still, solver.graphic()), 0.0) << "the hand stayed where it was";
  EXPECT_NE(reported_pairs(solver), before) << "other leaves near the fingertip";
  EXPECT_EQ(reported_pairs(solver), fresh_contacts(solver, &object, 1));
}

// An object the host moves into a still hand (a kinematic object, faster than Delta_r a
// step): the hand starts that step inside it, and is pushed back out within the step.
TEST(HandSolver, AnObjectMovedIntoTheHandPushesItOut) {
  HandScenario s;
  s.add(scenes::sample_tree("box"), {vec3(0.05, -0.02, -0.06), glm::dmat3(1.0)});  // top 2.5 cm under the palm
  HandSolver solver(default_model(), SolverParams{});
  const HandState still = scenes::open_hand();
  double deepest_after_step = 0.0;
  for (int t = 0; t < 60; ++t) {
    // the box rises 5 mm a step, up to 1 cm into where the palm is
    s.objects[0].pose.position.z = std::min(-0.06 + 0.005 * t, -0.0259 + 0.01);
    ASSERT_EQ(solver.step(still, s.objects.data(), 1, nullptr), FRUSTA_OK) << "step " << t;
    deepest_after_step = std::max(deepest_after_step,
                                  scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects));
  }
  EXPECT_LE(deepest_after_step, kMaxPenetration);
  EXPECT_GT(solver.graphic().palm_position.z, 0.009) << "pushed up by the box";
}

TEST(HandSolver, EqualRunsGiveEqualHands) {
  const HandScenario s = make_hand_scenario("ball_grasp");
  HandSolver a(default_model(), SolverParams{}), b(default_model(), SolverParams{});
  for (int t = 0; t < 150; ++t) {
    ASSERT_EQ(a.step(s.haptic(t), s.objects.data(), 1, nullptr), FRUSTA_OK);
    ASSERT_EQ(b.step(s.haptic(t), s.objects.data(), 1, nullptr), FRUSTA_OK);
    ASSERT_EQ(testing::state_change(a.graphic(), b.graphic()), 0.0) << "step " << t;
  }
}

// One untimed step against a scenario's one object, saying whether the caller vouches
// that the objects are as they were last step (HandSolver::step's objects_as_before).
frusta_result step_vouched(HandSolver& solver, const HandState& haptic, const HandScenario& s,
                           StepStats* stats, bool objects_as_before) {
  return solver.step(haptic, s.objects.data(), 1, stats, HandSolver::Clock::time_point::max(), nullptr,
                     objects_as_before);
}

// A caller that vouches for a still scene (objects_as_before) lets the solver keep what
// it detected for the bodies that did not move, and skip a hand at rest: nothing it
// computes may differ through the grasp (where no tree is walked for a still body) until
// the hand rests; then it stays within a standstill's creep of the hand solved on (which
// creeps on by less each step) and touches the same leaves.
TEST(HandSolver, KeepingTheLastStepsDetectionInAStillSceneChangesNothing) {
  const HandScenario s = make_hand_scenario("ball_grasp");
  HandSolver walked(default_model(), SolverParams{}), kept(default_model(), SolverParams{});
  int64_t walked_nodes = 0, kept_nodes = 0;
  int resting = 0;
  bool rested = false;
  constexpr int kHeld = 50;
  for (int t = 0; t < s.steps + kHeld; ++t) {
    const HandState& haptic = t < s.steps ? s.haptic(t) : s.held;
    StepStats a, b;
    ASSERT_EQ(walked.step(haptic, s.objects.data(), 1, &a), FRUSTA_OK);
    ASSERT_EQ(step_vouched(kept, haptic, s, &b, t > 0), FRUSTA_OK);
    ASSERT_FALSE(a.resting) << "at rest only in a scene vouched for";
    rested |= b.resting;
    // radians or metres: a nanometre's creep turns a joint by well under a microradian
    ASSERT_LE(testing::state_change(walked.graphic(), kept.graphic()), rested ? 1e-6 : 0.0) << "step " << t;
    ASSERT_EQ(walked.contacts().size(), kept.contacts().size()) << "step " << t;
    for (size_t i = 0; i < walked.contacts().size(); ++i) {
      ASSERT_EQ(walked.contacts()[i].leaf, kept.contacts()[i].leaf) << "step " << t;
      ASSERT_NEAR(walked.contacts()[i].distance, kept.contacts()[i].distance, rested ? 1e-8 : 0.0) << "step " << t;
    }
    if (t >= s.steps) {
      walked_nodes += a.tree_nodes_visited;
      kept_nodes += b.tree_nodes_visited;
      resting += b.resting ? 1 : 0;
    }
  }
  EXPECT_GT(walked_nodes, 0);
  EXPECT_EQ(kept_nodes, 0) << "a hand held still in a still scene walks no tree";
  EXPECT_GE(resting, kHeld - 5) << "a settled hand is not solved again";
}

// Rest ends as soon as anything it rests on changes: the target, or the objects.
TEST(HandSolver, AHandAtRestIsSolvedAgainWhenItsTargetOrTheObjectsChange) {
  HandScenario s = make_hand_scenario("box_press");
  HandSolver solver(default_model(), SolverParams{});
  StepStats stats;
  for (int t = 0; t < s.steps + 20; ++t)
    ASSERT_EQ(step_vouched(solver, t < s.steps ? s.haptic(t) : s.held, s, &stats, t > 0), FRUSTA_OK);
  ASSERT_TRUE(stats.resting) << "settled on the box";
  // the haptic fingertip lifts off: solved again, and the graphic one follows it up
  HandState lifted = s.held;
  lifted.palm_position.z += 0.01;
  ASSERT_EQ(step_vouched(solver, lifted, s, &stats, true), FRUSTA_OK);
  EXPECT_FALSE(stats.resting);
  EXPECT_GT(solver.graphic().palm_position.z, s.held.palm_position.z);
  for (int t = 0; t < 20; ++t)
    ASSERT_EQ(step_vouched(solver, s.held, s, &stats, true), FRUSTA_OK);
  ASSERT_TRUE(stats.resting);
  // the box moves into the finger, and the caller says so: pushed out, not left inside
  s.objects[0].pose.position.z += 0.003;
  ASSERT_EQ(step_vouched(solver, s.held, s, &stats, false), FRUSTA_OK);
  EXPECT_FALSE(stats.resting);
  EXPECT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), kMaxPenetration);
}

// A hand among still objects asks the broad phase about a box a little larger than a
// sub-step needs, and asks again only when it leaves that box or objects move: a held
// grasp (a tremor of 0.1 mm, every step solved) asks nothing. Its hands and contacts
// are those of a solver looking at every object.
TEST(HandSolver, AHandAmongStillObjectsAsksTheBroadPhaseAgainOnlyWhenItLeavesItsBox) {
  HandScenario s = scenes::ball_grasp(scenes::ball_shell(2000, 0.04));
  // props of the same ball around it, 0.2-0.5 m from its centre: some in the box the
  // grasp asks about
  const RigidPose ball = s.objects[0].pose;
  for (int k = 0; k < 12; ++k) {
    const double a = 0.5 * k, r = 0.2 + 0.025 * k;
    s.add(s.trees[0], {ball.position + r * vec3(std::cos(a), std::sin(a), 0.3 * std::sin(2.0 * a)), ball.rotation});
  }
  testing::SceneFinder finder(s.objects);
  HandSolver every(default_model(), SolverParams{}), found(default_model(), SolverParams{});
  const int32_t count = static_cast<int32_t>(s.objects.size());
  auto step_both = [&](const HandState& haptic, bool as_before, StepStats& stats) {
    ASSERT_EQ(every.step(haptic, s.objects.data(), count, nullptr, HandSolver::Clock::time_point::max(),
                         nullptr, as_before),
              FRUSTA_OK);
    ASSERT_EQ(found.step(haptic, s.objects.data(), count, &stats, HandSolver::Clock::time_point::max(),
                         &finder, as_before),
              FRUSTA_OK);
    ASSERT_TRUE(scenes::same_bits(every.graphic(), found.graphic()));
    ASSERT_EQ(every.contacts().size(), found.contacts().size());
    for (size_t i = 0; i < every.contacts().size(); ++i)
      ASSERT_EQ(every.contacts()[i].distance, found.contacts()[i].distance);
  };
  StepStats stats;
  int64_t substeps = 0;
  for (int t = 0; t < s.steps; ++t) {
    step_both(s.haptic(t), t > 0, stats);
    substeps += stats.substeps;
  }
  EXPECT_LT(finder.finds(), substeps / 4) << "the grasp's approach asked each sub-step";
  const int64_t before_hold = finder.finds();
  constexpr int kHeld = 200;
  for (int t = 0; t < kHeld; ++t) {
    HandState held = s.held;
    held.palm_position.z += 1e-4 * std::sin(0.05 * (t + 1));
    step_both(held, true, stats);
    ASSERT_FALSE(stats.resting);
  }
  EXPECT_EQ(finder.finds(), before_hold) << "a held grasp asked the broad phase again";
  // a prop moves (the caller says so): asked again, once
  s.objects[1].pose.position.x += 0.01;
  finder.moved(s.objects, 1);
  step_both(s.held, false, stats);
  EXPECT_EQ(finder.finds(), before_hold + 1);
  // the hand goes 5 cm to the side, beyond the room it asked with: asked again
  HandState aside = s.held;
  aside.palm_position.y += 0.05;
  const int64_t before_aside = finder.finds();
  for (int t = 0; t < 50; ++t) step_both(aside, true, stats);
  EXPECT_GT(finder.finds(), before_aside);
}

// A finger pressed deep into a curved surface creeps along it as its linearisations
// converge, less each step (on this ball for some 50 steps after the haptic hand
// stops); once a step has moved the hand by no more than the solver's standstill (a
// nanometre, bounded as the solver bounds motion), the same inputs leave it at rest.
TEST(HandSolver, AHandCreepingLessThanANanometreAStepRests) {
  const HandScenario s = scenes::ball_grasp(scenes::ball_shell(2000, 0.04));
  HandSolver solver(default_model(), SolverParams{});
  const HandReach reach = hand_reach(solver.model());
  auto moved = [&](const HandState& a, const HandState& b) {
    double m = palm_motion(reach, {a.palm_position, a.palm_rotation}, {b.palm_position, b.palm_rotation});
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      FingerAngles from, to;
      std::copy_n(a.angles.begin() + f * FRUSTA_JOINTS_PER_FINGER, from.size(), from.begin());
      std::copy_n(b.angles.begin() + f * FRUSTA_JOINTS_PER_FINGER, to.size(), to.begin());
      m += finger_lever_motion(reach, f, from, to);
    }
    return m;
  };
  bool crept = false;  // the last step moved the hand, by no more than a nanometre
  int32_t checked = 0;
  HandState last_haptic = s.haptic(0);
  for (int t = 0; t < s.steps + 100; ++t) {
    const HandState haptic = t < s.steps ? s.haptic(t) : s.held;
    const HandState before = solver.graphic();
    StepStats stats;
    ASSERT_EQ(step_vouched(solver, haptic, s, &stats, t > 0), FRUSTA_OK);
    if (crept && testing::state_change(haptic, last_haptic) == 0.0) {
      EXPECT_TRUE(stats.resting) << "step " << t;
      ++checked;
    }
    const double m = moved(before, solver.graphic());
    crept = m > 0.0 && m <= 1e-9 && !stats.lagging && !stats.rate_limited;
    last_haptic = haptic;
  }
  EXPECT_GT(checked, 0) << "the grasp crept";
  EXPECT_TRUE(solver.contacts().size() > 0);
}

// A sub-step moves no finger point further than Delta_r, by the finger's pose's motion
// bound (what the sub-step's detection covers), though its levers' bound may go further
// where the budget allows: a closing grasp's fingers reach in one sub-step what the
// levers' bound split over two. Checked on every step that took one sub-step with the
// palm still, in the grasp with a generous budget and every scenario.
TEST(HandSolver, ASubStepMovesNoFingerFurtherThanDeltaRByItsPose) {
  const HandModel model = default_model();
  const HandReach reach = hand_reach(model);
  SolverParams generous;
  generous.follow_factor = 4.0;
  int32_t checked = 0, past_levers = 0;
  auto run = [&](const HandScenario& s, const SolverParams& params, const std::string& name) {
    HandSolver solver(model, params);
    for (int t = 0; t < s.steps; ++t) {
      const HandState before = solver.graphic();
      const HandPose posed = solver.graphic_pose();
      const bool started = solver.started();
      StepStats stats;
      ASSERT_EQ(solver.step(s.haptic(t), s.objects.data(), static_cast<int32_t>(s.objects.size()), &stats),
                FRUSTA_OK);
      const HandState& after = solver.graphic();
      if (!started || stats.substeps != 1 || before.palm_position != after.palm_position ||
          before.palm_rotation != after.palm_rotation)
        continue;
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
        FingerAngles from, to;
        std::copy_n(before.angles.begin() + f * FRUSTA_JOINTS_PER_FINGER, from.size(), from.begin());
        std::copy_n(after.angles.begin() + f * FRUSTA_JOINTS_PER_FINGER, to.size(), to.begin());
        ASSERT_LE(finger_motion(model, reach, posed.fingers[f], f, from, to),
                  params.prediction_margin * (1.0 + 1e-9))
            << name << " step " << t << " finger " << f;
        past_levers += finger_lever_motion(reach, f, from, to) > params.prediction_margin ? 1 : 0;
        ++checked;
      }
    }
  };
  run(scenes::ball_grasp(scenes::ball_shell(2000, 0.04)), generous, "grasp");
  for (const std::string& name : scenes::hand_scenario_names()) run(make_hand_scenario(name), SolverParams{}, name);
  EXPECT_GT(checked, 5000);
  EXPECT_GT(past_levers, 20) << "the levers' bound went past Delta_r in one sub-step";
}

// A finger at rest is not solved again while the others are: held still, the 10^4-leaf
// grasp had all five fingers solved on every step until the last one's creep (by under
// a nanometre a step, converging) stopped, though four had stopped long before. Solved
// with and without the rest (a caller not vouching for the scene has none), every
// scenario's hand stays within a nanometre creep's reach of the other and touches the
// same leaves.
TEST(HandSolver, AFingerAtRestIsNotSolvedAgainWhileAnotherCreeps) {
  int32_t fingers_skipped = 0;
  for (const std::string& name : scenes::hand_scenario_names()) {
    const HandScenario s = make_hand_scenario(name);
    if (s.objects.size() != 1) continue;  // step_vouched steps against one object
    HandSolver walked(default_model(), SolverParams{}), kept(default_model(), SolverParams{});
    int32_t walked_solves = 0, kept_solves = 0;
    for (int t = 0; t < s.steps + 60; ++t) {
      const HandState& haptic = t < s.steps ? s.haptic(t) : s.held;
      StepStats a, b;
      ASSERT_EQ(step_vouched(walked, haptic, s, &a, false), FRUSTA_OK);
      ASSERT_EQ(step_vouched(kept, haptic, s, &b, t > 0), FRUSTA_OK);
      ASSERT_EQ(a.resting_fingers, 0u) << "at rest only in a scene vouched for";
      ASSERT_LE(testing::state_change(walked.graphic(), kept.graphic()), 1e-6)
          << name << " step " << t;
      ASSERT_EQ(walked.contacts().size(), kept.contacts().size()) << name << " step " << t;
      for (size_t i = 0; i < walked.contacts().size(); ++i)
        ASSERT_EQ(walked.contacts()[i].leaf, kept.contacts()[i].leaf) << name << " step " << t;
      walked_solves += a.finger_solves;
      kept_solves += b.finger_solves;
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        fingers_skipped += !b.resting && ((b.resting_fingers >> f) & 1u) != 0 ? 1 : 0;
    }
    EXPECT_LE(kept_solves, walked_solves) << name;
  }
  std::printf("[ finger rest ] %d fingers at rest in steps that solved the hand\n",
              fingers_skipped);
  EXPECT_GT(fingers_skipped, 100) << "fingers at rest in steps that solved the hand";
}

// A grasp of a coarse ball (100 leaves of ~8 mm) held still comes to rest. Before, the
// little fingertip slid a few microns a step towards its target (each step further:
// the fixed point there is unstable) until its budget cut a step short, and that
// step's slide took it back past where it began: a five-step cycle of 4-36 um for as
// long as the hand was held, never at rest.
TEST(HandSolver, AGraspOfACoarseBallHeldStillComesToRest) {
  const HandScenario s = scenes::ball_grasp(scenes::ball_shell(100, 0.04));
  HandSolver solver(default_model(), SolverParams{});
  StepStats stats;
  for (int t = 0; t < s.steps; ++t) ASSERT_EQ(step_vouched(solver, s.haptic(t), s, &stats, t > 0), FRUSTA_OK);
  int32_t resting = 0;
  for (int t = 0; t < 200; ++t) {
    ASSERT_EQ(step_vouched(solver, s.held, s, &stats, true), FRUSTA_OK);
    resting += stats.resting ? 1 : 0;
  }
  EXPECT_TRUE(stats.resting);
  EXPECT_GE(resting, 150) << "held still, the hand is still";
  EXPECT_LE(scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects), kMaxPenetration);
  EXPECT_FALSE(solver.contacts().empty());
}

// A grasp held on a level of detail keeps its contacts. Before, the 10^5-leaf ball at a
// 1 mm budget lost every contact in five held steps of six: a slow hand's small margin
// missed the nodes standing in (they stick out of their parents), so the hand moved in,
// and a larger margin found them again with the hand inside and pushed it out.
TEST(HandSolver, AGraspHeldOnALevelOfDetailKeepsItsContacts) {
  const HandScenario s = scenes::ball_grasp(scenes::ball_shell(100000, 0.04));
  SolverParams params;
  params.lod_error = 0.001;
  HandSolver solver(default_model(), params);
  StepStats stats;
  for (int t = 0; t < s.steps; ++t) ASSERT_EQ(step_vouched(solver, s.haptic(t), s, &stats, t > 0), FRUSTA_OK);
  int32_t without = 0, resting = 0;
  for (int t = 0; t < 100; ++t) {
    ASSERT_EQ(step_vouched(solver, s.held, s, &stats, true), FRUSTA_OK);
    without += solver.contacts().empty() ? 1 : 0;
    resting += stats.resting ? 1 : 0;
  }
  EXPECT_EQ(without, 0) << "held steps without a contact";
  EXPECT_GE(resting, 90);
}

// A slow hand looks only as far as it can move (detection_margin): a grasp held with a
// steady hand's tremor meets a fraction of the candidates a Delta_r detection finds,
// keeps its contacts, and never sinks past the floor.
TEST(HandSolver, ASlowHandDetectsOnlyAsFarAsItCanMove) {
  const HandScenario s = make_hand_scenario("ball_grasp");
  HandSolver solver(default_model(), SolverParams{});
  testing::RunLog log = testing::run(solver, s);
  double deepest = log.max_penetration;
  int32_t fewest = INT32_MAX;
  for (int t = 0; t < 400; ++t) {
    HandState trembling = s.held;
    trembling.palm_position.z += 1e-4 * std::sin(2.0 * glm::pi<double>() * 8.0 * 1e-3 * t);  // 0.1 mm at 8 Hz
    StepStats stats;
    ASSERT_EQ(step_vouched(solver, trembling, s, &stats, true), FRUSTA_OK);
    if (t >= 100) fewest = std::min(fewest, stats.candidates);
    deepest = std::max(deepest, scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects));
    ASSERT_FALSE(solver.contacts().empty()) << "step " << t;
  }
  CandidateSet full;
  detect_candidates(solver.model(), hand_reach(solver.model()), solver.graphic_pose(), s.objects.data(), 1,
                    SolverParams{}.prediction_margin, TreeCut(-1, 0.0), full);
  EXPECT_LT(4 * fewest, full.size())
      << "a hand moving microns a step looks a fraction of Delta_r away";
  EXPECT_LE(deepest, kMaxPenetration);
  for (int f = 1; f < 5; ++f) EXPECT_TRUE(touches(solver, f)) << "finger " << f << " still holds the ball";
}

TEST(HandSolver, ParametersAreCheckedByName) {
  const HandModel model = default_model();
  SolverParams p;
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_OK);
  p.prediction_margin = 0.05;  // more than a finger's radius: a sub-step could tunnel
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("prediction_margin"), std::string::npos);
  p = SolverParams{};
  p.joint_stiffness[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("joint_stiffness[2]"), std::string::npos);
}

}  // namespace
}  // namespace frusta
