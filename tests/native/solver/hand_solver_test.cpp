// SPDX-License-Identifier: MIT
// The graphic hand on scripted haptic trajectories (issue: the non-penetrating solve).
// Every scenario checks the floor: the graphic hand never sinks more than 0.05 mm into
// the exact leaf-sphere set, and held still in contact it neither drifts nor rocks.
#include "solver/hand_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtx/quaternion.hpp>

#include "bake/baker.h"
#include "hand/hand_model.h"
#include "scenario.h"
#include "scenes/meshes.h"

namespace frusta {
namespace {

using testing::Scene;

constexpr double kMaxPenetration = 0.05e-3;  // the acceptance floor, metres
constexpr double kMaxDrift = 1e-6;           // rad (and m) over 1,000 held steps
constexpr int kHoldSteps = 1000;

HandModel default_model() { return make_hand_model(frusta_default_hand_def()); }

HandState open_hand(const vec3& palm = vec3(0.0), const glm::dquat& rotation = glm::dquat(1, 0, 0, 0)) {
  HandState s;
  s.palm_position = palm;
  s.palm_rotation = rotation;
  return s;
}

HandState mix(const HandState& a, const HandState& b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  HandState s;
  s.palm_position = a.palm_position + t * (b.palm_position - a.palm_position);
  s.palm_rotation = glm::slerp(a.palm_rotation, b.palm_rotation, t);
  for (size_t j = 0; j < s.angles.size(); ++j) s.angles[j] = a.angles[j] + t * (b.angles[j] - a.angles[j]);
  return s;
}

void set_flexion(HandState& s, int finger, double f1, double f2, double f3) {
  s.angles[finger * 4 + 1] = f1;
  s.angles[finger * 4 + 2] = f2;
  s.angles[finger * 4 + 3] = f3;
}

// The floor every contact scenario shares: hold, then bad input leaves the hand intact.
void expect_holds_and_rejects_bad_input(HandSolver& solver, const Scene& scene, const HandState& held,
                                        testing::RunLog& log) {
  const double drift = testing::hold_drift(solver, scene, held, kHoldSteps, log);
  EXPECT_LT(drift, kMaxDrift) << "graphic hand moved while the haptic hand was held still";
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  const HandState before = solver.graphic();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  HandState bad = held;
  bad.angles[6] = nan;
  EXPECT_EQ(solver.step(bad, scene.objects.data(), static_cast<int32_t>(scene.objects.size()), nullptr),
            FRUSTA_ERROR_NOT_FINITE);
  bad = held;
  bad.palm_position.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(solver.step(bad, scene.objects.data(), static_cast<int32_t>(scene.objects.size()), nullptr),
            FRUSTA_ERROR_NOT_FINITE);
  bad = held;
  bad.palm_position.x = 1e9;  // a kilometre-scale glove reading is garbage
  EXPECT_EQ(solver.step(bad, scene.objects.data(), static_cast<int32_t>(scene.objects.size()), nullptr),
            FRUSTA_ERROR_OUT_OF_RANGE);
  bad = held;
  bad.palm_rotation = glm::dquat(0, 0, 0, 0);
  EXPECT_EQ(solver.step(bad, scene.objects.data(), static_cast<int32_t>(scene.objects.size()), nullptr),
            FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(testing::state_change(before, solver.graphic()), 0.0) << "bad input changed the graphic hand";
}

// Boxes baked here rather than shipped: one larger than the hand (coarse: what matters
// is the interior fill) and a small plate that fits between two finger pads.
std::shared_ptr<TreeFile> baked_box(const vec3& size, double target_error) {
  auto file = std::make_shared<TreeFile>();
  BakeParams params;
  params.target_error = target_error;
  bool met = false;
  EXPECT_EQ(bake_sphere_tree(scenes::make_box(size, 4), params, nullptr, file.get(), &met), FRUSTA_OK);
  return file;
}

TEST(HandSolver, InFreeSpaceTheGraphicHandIsTheHapticHand) {
  Scene scene;
  scene.add("ball", {vec3(1.0, 0.0, 0.0), glm::dmat3(1.0)});  // a metre away
  HandSolver solver(default_model(), SolverParams{});
  for (int t = 0; t < 300; ++t) {
    HandState h = open_hand(vec3(0.001 * t, 0.0, 0.0005 * t), testing::about(vec3(1, 2, 3), 0.01 * t));
    for (size_t j = 0; j < h.angles.size(); ++j) h.angles[j] = 0.8 * std::sin(0.05 * t + static_cast<double>(j));
    StepStats stats;
    ASSERT_EQ(solver.step(h, scene.objects.data(), 1, &stats), FRUSTA_OK);
    HandState clamped = h;
    clamp_to_limits(solver.model(), clamped);
    ASSERT_LT(testing::state_change(clamped, solver.graphic()), 1e-9) << "step " << t;
    EXPECT_EQ(stats.finger_solves + stats.palm_solves, 0) << "nothing near: nothing to solve";
    EXPECT_TRUE(solver.contacts().empty());
  }
}

TEST(HandSolver, FingertipPressedIntoABoxFaceStopsOnIt) {
  Scene scene;
  scene.add("box", {vec3(0.175, 0.034, -0.045), glm::dmat3(1.0)});  // top face at z = -25 mm
  HandSolver solver(default_model(), SolverParams{});
  HandState pressed = open_hand();
  set_flexion(pressed, 1, 0.9, 0.9, 0.6);  // the index would end 3 cm inside the box
  testing::RunLog log = testing::run(solver, scene, 200, [&](int t) { return mix(open_hand(), pressed, t / 150.0); });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  EXPECT_FALSE(solver.contacts().empty());
  EXPECT_LT(solver.graphic().angles[5], pressed.angles[5] - 0.1) << "the index stopped short";
  for (const SolverContact& c : solver.contacts()) EXPECT_EQ(c.body / 3, 1) << "only the index touches";
  expect_holds_and_rejects_bad_input(solver, scene, pressed, log);
}

TEST(HandSolver, DeepGraspOfABallLeavesEveryFingerOnItsSurface) {
  Scene scene;
  scene.add("ball", {vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)});  // 4 cm radius, under the palm
  HandSolver solver(default_model(), SolverParams{});
  HandState closed = open_hand();
  for (int f = 0; f < 5; ++f) set_flexion(closed, f, 1.6, 1.6, 1.6);
  testing::RunLog log = testing::run(solver, scene, 300, [&](int t) { return mix(open_hand(), closed, t / 250.0); });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  bool touching[5] = {};
  for (const SolverContact& c : solver.contacts())
    if (c.body < 15) touching[c.body / 3] = true;
  for (int f = 1; f < 5; ++f) EXPECT_TRUE(touching[f]) << "finger " << f << " wraps the ball";
  expect_holds_and_rejects_bad_input(solver, scene, closed, log);
}

TEST(HandSolver, FingertipSlidesAlongASurfaceWithoutSinking) {
  Scene scene;
  scene.add("box", {vec3(0.175, 0.034, -0.045), glm::dmat3(1.0)});
  HandSolver solver(default_model(), SolverParams{});
  HandState pressed = open_hand();
  set_flexion(pressed, 1, 0.6, 0.6, 0.4);
  HandState slid = pressed;
  slid.palm_position = vec3(0.03, 0.0, 0.0);
  testing::RunLog log = testing::run(solver, scene, 400, [&](int t) {
    return t < 100 ? mix(open_hand(), pressed, t / 80.0) : mix(pressed, slid, (t - 100) / 250.0);
  });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  // the palm carries the index rigidly over the leaves' bumps, so it may lag a little
  EXPECT_NEAR(solver.graphic().palm_position.x, 0.03, 1e-4) << "the palm slid (nearly) all the way";
  EXPECT_FALSE(solver.contacts().empty()) << "still pressing at the end";
  expect_holds_and_rejects_bad_input(solver, scene, slid, log);
}

TEST(HandSolver, ThumbAndIndexPinchAThinPlate) {
  // a pinch pose found by search: thumb and index pads 4 mm apart, the plate between
  HandState pinch = open_hand();
  pinch.angles = {-0.1, 0.4, 0.4, 0.3, 0.0, 0.4, 1.1, 0.3};
  const HandModel model = default_model();
  HandPose pose;
  forward_kinematics(model, pinch, pose);
  const vec3 thumb = pose.fingers[0].joint[3], index = pose.fingers[1].joint[3];
  const vec3 normal = glm::normalize(index - thumb);
  const vec3 centre = thumb + normal * (model.fingers[0].radius[3] + 0.002);
  static const std::shared_ptr<TreeFile> plate = baked_box(vec3(0.03, 0.03, 0.004), 0.001);
  Scene scene;
  scene.objects.push_back({&plate->tree, {centre, glm::mat3_cast(glm::rotation(vec3(0, 0, 1), normal))}});

  // each pad pushed along the plate's normal through it: the joint motion that moves
  // its tip centre a distance along a direction, to first order (Jacobian transpose)
  auto pushed = [&](const HandState& from, int finger, const vec3& direction, double distance) {
    double j[3 * kJacobianColumns];
    point_jacobian(pose, finger, 2, pose.fingers[finger].joint[3], j);
    double step[4], tip[3] = {};
    for (int c = 0; c < 4; ++c) step[c] = j[c] * direction.x + j[kJacobianColumns + c] * direction.y +
                                          j[2 * kJacobianColumns + c] * direction.z;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) tip[r] += j[r * kJacobianColumns + c] * step[c];
    const double scale = distance / std::sqrt(tip[0] * tip[0] + tip[1] * tip[1] + tip[2] * tip[2]);
    HandState out = from;
    for (int c = 0; c < 4; ++c) out.angles[finger * 4 + c] += scale * step[c];
    return out;
  };
  const HandState before = pushed(pushed(pinch, 0, -normal, 0.008), 1, normal, 0.008);
  const HandState through = pushed(pushed(pinch, 0, normal, 0.01), 1, -normal, 0.01);
  HandSolver solver(model, SolverParams{});
  StepStats first;
  ASSERT_EQ(solver.step(open_hand(), scene.objects.data(), 1, &first), FRUSTA_OK);
  ASSERT_FALSE(first.depenetrated) << "the scene must start free for the test to mean anything";
  testing::RunLog log = testing::run(solver, scene, 300, [&](int t) {
    return t < 120 ? mix(open_hand(), before, t / 100.0) : mix(before, through, (t - 120) / 120.0);
  });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  bool thumb_touches = false, index_touches = false;
  for (const SolverContact& c : solver.contacts()) {
    thumb_touches |= c.body / 3 == 0;
    index_touches |= c.body / 3 == 1;
  }
  EXPECT_TRUE(thumb_touches);
  EXPECT_TRUE(index_touches);
  const HandPose& g = solver.graphic_pose();
  EXPECT_LT(glm::dot(g.fingers[0].joint[3] - centre, normal), 0.0) << "thumb stays on its side";
  EXPECT_GT(glm::dot(g.fingers[1].joint[3] - centre, normal), 0.0) << "index stays on its side";
  expect_holds_and_rejects_bad_input(solver, scene, through, log);
}

TEST(HandSolver, FingersPressIntoAConcaveBowl) {
  Scene scene;
  scene.add("bowl", {vec3(0.13, 0.0, -0.01), glm::dmat3(1.0)});
  HandSolver solver(default_model(), SolverParams{});
  const HandState above = open_hand(vec3(0.0, 0.0, 0.06));
  HandState pressed = open_hand(vec3(0.0, 0.0, -0.02));
  for (int f = 1; f < 5; ++f) set_flexion(pressed, f, 0.5, 0.6, 0.4);
  testing::RunLog log = testing::run(solver, scene, 300, [&](int t) { return mix(above, pressed, t / 250.0); });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  EXPECT_FALSE(solver.contacts().empty());
  expect_holds_and_rejects_bad_input(solver, scene, pressed, log);
}

TEST(HandSolver, HapticHandTeleportingThroughAPlateLeavesTheGraphicHandOnTop) {
  Scene scene;
  scene.add("plate", {vec3(0.10, 0.0, -0.027), glm::dmat3(1.0)});  // top at -25 mm, 4 mm thick
  HandSolver solver(default_model(), SolverParams{});
  const HandState below = open_hand(vec3(0.0, 0.0, -0.05));  // wholly under the plate
  testing::RunLog log = testing::run(solver, scene, 300, [&](int t) { return t < 10 ? open_hand() : below; });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  // every joint and palm sphere over the plate's footprint stayed above it
  const HandPose& g = solver.graphic_pose();
  auto above_footprint = [](const vec3& p) { return std::fabs(p.x - 0.10) < 0.06 && std::fabs(p.y) < 0.04; };
  int over = 0;
  for (int k = 0; k < static_cast<int>(solver.model().palm_spheres.size()); ++k) {
    const vec3 c = palm_sphere(solver.model(), g, k).center;
    if (!above_footprint(c)) continue;
    EXPECT_GT(c.z, -0.025) << "palm sphere " << k;
    ++over;
  }
  for (int f = 0; f < 5; ++f)
    for (const vec3& j : g.fingers[f].joint) {
      if (!above_footprint(j)) continue;
      EXPECT_GT(j.z, -0.025) << "finger " << f;
      ++over;
    }
  EXPECT_GT(over, 20) << "most of the hand is over the plate";
  EXPECT_FALSE(solver.contacts().empty()) << "resting on the plate";
  expect_holds_and_rejects_bad_input(solver, scene, below, log);
}

TEST(HandSolver, HapticHandStartingInsideAnObjectIsPlacedOutside) {
  static const std::shared_ptr<TreeFile> box = baked_box(vec3(0.40, 0.30, 0.16), 0.004);
  Scene scene;
  scene.objects.push_back({&box->tree, {vec3(0.08, 0.0, 0.0), glm::dmat3(1.0)}});
  HandSolver solver(default_model(), SolverParams{});
  HandState inside = open_hand();
  set_flexion(inside, 2, 0.3, 0.3, 0.3);
  StepStats first;
  ASSERT_EQ(solver.step(inside, scene.objects.data(), 1, &first), FRUSTA_OK);
  EXPECT_TRUE(first.depenetrated);
  EXPECT_LE(testing::deepest_penetration(solver.model(), solver.graphic_pose(), scene.objects), kMaxPenetration);
  // out through the nearest face (z, 8 cm away) rather than any other
  EXPECT_GT(std::fabs(solver.graphic().palm_position.z), 0.08);
  testing::RunLog log = testing::run(solver, scene, 200, [&](int) { return inside; });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  expect_holds_and_rejects_bad_input(solver, scene, inside, log);
}

TEST(HandSolver, PalmPressedFlatOnABoxThenFingersClose) {
  Scene scene;
  // top face 1 mm under the palm; off to the little finger's side, so the thumb's
  // metacarpal (which hangs below the palm's plane) is beside the box, not on it
  scene.add("box", {vec3(0.05, -0.02, -0.0359), glm::dmat3(1.0)});
  HandSolver solver(default_model(), SolverParams{});
  const HandState pressed = open_hand(vec3(0.0, 0.0, -0.01));
  HandState closed = pressed;
  for (int f = 0; f < 5; ++f) set_flexion(closed, f, 1.6, 1.6, 1.6);
  testing::RunLog log = testing::run(solver, scene, 400, [&](int t) {
    return t < 100 ? mix(open_hand(), pressed, t / 80.0) : mix(pressed, closed, (t - 100) / 250.0);
  });
  EXPECT_LE(log.max_penetration, kMaxPenetration);
  EXPECT_GT(solver.graphic().palm_position.z, -0.0015) << "the palm rests on the box top";
  bool palm_touches = false;
  for (const SolverContact& c : solver.contacts()) palm_touches |= c.body == kPalmBody;
  EXPECT_TRUE(palm_touches);
  expect_holds_and_rejects_bad_input(solver, scene, closed, log);
}

TEST(HandSolver, EqualRunsGiveEqualHands) {
  Scene scene;
  scene.add("ball", {vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)});
  HandState closed = open_hand();
  for (int f = 0; f < 5; ++f) set_flexion(closed, f, 1.6, 1.6, 1.6);
  HandSolver a(default_model(), SolverParams{}), b(default_model(), SolverParams{});
  for (int t = 0; t < 150; ++t) {
    const HandState h = mix(open_hand(), closed, t / 100.0);
    ASSERT_EQ(a.step(h, scene.objects.data(), 1, nullptr), FRUSTA_OK);
    ASSERT_EQ(b.step(h, scene.objects.data(), 1, nullptr), FRUSTA_OK);
    ASSERT_EQ(testing::state_change(a.graphic(), b.graphic()), 0.0) << "step " << t;
  }
}

TEST(HandSolver, ParametersAreCheckedByName) {
  const HandModel model = default_model();
  SolverParams p;
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_OK);
  p.prediction_margin = 0.05;  // more than a finger's radius: a sub-step could tunnel
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta_last_error()).find("prediction_margin"), std::string::npos);
  p = SolverParams{};
  p.joint_stiffness[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(HandSolver::check_params(p, model), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta_last_error()).find("joint_stiffness[2]"), std::string::npos);
}

}  // namespace
}  // namespace frusta
