// SPDX-License-Identifier: MIT
// The forces a world publishes and the objects it moves, end to end through its step:
// a fingertip pressed a known depth into a baked box pushes back with stiffness times
// depth however many leaves it touches; what the hands feel balances what the objects
// receive; a dynamic object falls exactly as the integrator says, and a ball grasped
// by a closing hand is lifted, carried and dropped by the contact forces alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "hand/anthropometry.h"
#include "core/error.h"
#include "hand/hand_model.h"
#include "runtime/world.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"
#include "scenes/jittery_host.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

constexpr int kIndex = 1;
constexpr int kIndexTip = kIndex * FRUSTA_SEGMENTS_PER_FINGER + 2;

HandModel right_hand() { return make_hand_model(default_hand_def()); }

HandPose pose_of(const HandModel& model, const HandState& state) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  return pose;
}

HandHandle add_hand(World& world, const HandModel& model) {
  HandHandle hand;
  EXPECT_EQ(world.add_hand(model, &hand), FRUSTA_OK);
  return hand;
}

// A dynamic ball of `mass` kg and `radius` m (a solid one's inertia), damped a little.
ObjectDef ball_def(const RigidPose& pose, double mass, double radius) {
  ObjectDef ball;
  ball.pose = pose;
  ball.mass = mass;
  ball.inertia = vec3(0.4 * mass * radius * radius);
  ball.linear_damping = ball.angular_damping = 0.5;
  return ball;
}

// 0 to 1 with zero velocity at both ends: a hand carrying something starts and stops gently
double smooth(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

vec3 total_force(const ContactForce& c) { return c.normal_force + c.friction; }

TEST(WorldForces, FingertipPressedIntoABakedBoxFeelsStiffnessTimesDepth) {
  // a 2 cm box whose top face touches the open hand's index fingertip from below
  const HandModel model = right_hand();
  const HandPose open = pose_of(model, scenes::open_hand());
  const vec3 tip = open.fingers[kIndex].joint[3];
  const double half = 0.5 * scenes::test_box_spec("fingertip_box").size.x;
  // from 5 mm behind the tip's centre on: under the distal segment only
  const vec3 centre =
      tip + vec3(half - 0.005, 0.0, -(model.fingers[kIndex].radius[3] + half));
  ObjectDef box;
  box.pose.position = centre;
  box.material.normal_stiffness = vec3(600.0);
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, model);
  ObjectHandle handle;
  ASSERT_EQ(world.add_object(scenes::test_box("fingertip_box"), box, &handle), FRUSTA_OK);

  for (double depth : {0.001, 0.003, 0.006}) {
    // the hand lowered; the solver keeps the fingertip on the face (the palm pivots a
    // little about it), so the gap P_ig - P_ih is measured, not assumed
    for (int t = 0; t < 20; ++t) {
      world.set_haptic(hand, scenes::open_hand(vec3(0.0, 0.0, -depth)));
      world.step();
    }
    const WorldSnapshot& snap = world.read();
    const HandSnapshot& h = *snap.hand(hand);
    ASSERT_GT(h.contact_count, 2) << "the tip rests on several leaves";
    vec3 on_tip(0.0), friction(0.0);
    double gap = 0.0;
    for (int32_t i = 0; i < h.contact_count; ++i) {
      const ContactForce& c = h.forces[static_cast<size_t>(i)];
      ASSERT_EQ(c.body, kIndexTip);
      on_tip += c.normal_force;
      friction += c.friction;
      gap += glm::length(c.graphic_point - c.haptic_point) / h.contact_count;
    }
    EXPECT_GT(gap, depth) << "at least the depth the hand was lowered";
    // one face's worth, however many leaves: the leaves' caps tilt their normals a few
    // degrees off the face's, which shortens the sum by their spread only
    EXPECT_NEAR(glm::length(on_tip), 600.0 * gap, 0.02 * 600.0 * gap) << depth;
    EXPECT_GT(on_tip.z, 0.98 * glm::length(on_tip)) << "out of the top face";
    const vec3 total = on_tip + friction;
    EXPECT_NEAR(glm::length(h.device.fingertip_force[kIndex]), glm::length(total), 1e-9);
    EXPECT_NEAR(h.device.finger_resistance[kIndex], glm::length(total), 1e-9);
  }
}

TEST(WorldForces, WhatTheHandsFeelBalancesWhatTheObjectsReceive) {
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(500, 0.04);
  const scenes::HandScenario grasp = scenes::ball_grasp(ball);
  World world(WorldDef{});
  const HandModel right = right_hand();
  const HandHandle first = add_hand(world, right), second = add_hand(world, right);
  ObjectHandle a, b;
  ASSERT_EQ(world.add_object(ball, grasp.objects[0].pose, &a), FRUSTA_OK);
  RigidPose shifted = grasp.objects[0].pose;
  shifted.position.y += 0.5;
  ASSERT_EQ(world.add_object(ball, shifted, &b), FRUSTA_OK);
  for (int32_t t = 0; t < grasp.steps; ++t) {
    world.set_haptic(first, grasp.haptic(t));
    HandState other = grasp.haptic(t);
    other.palm_position.y += 0.5;
    world.set_haptic(second, other);
    world.step();
  }
  const WorldSnapshot& snap = world.read();
  vec3 force(0.0), torque(0.0);  // on the hands, torque about the origin
  for (HandHandle hand : {first, second}) {
    const HandSnapshot& h = *snap.hand(hand);
    ASSERT_GT(h.force_stats.pressing, 3);
    for (int32_t i = 0; i < h.contact_count; ++i) {
      const ContactForce& c = h.forces[static_cast<size_t>(i)];
      force += total_force(c);
      torque += glm::cross(c.graphic_point, total_force(c));
    }
  }
  vec3 reaction(0.0), reaction_torque(0.0);
  for (const ObjectSnapshot& o : snap.objects) {
    if (!o.present) continue;
    reaction += o.reaction.force;
    reaction_torque += o.reaction.torque + glm::cross(o.pose.position, o.reaction.force);
  }
  ASSERT_GT(glm::length(force), 1.0);
  const double scale = glm::length(force);
  EXPECT_LT(glm::length(force + reaction), 1e-12 * scale);
  EXPECT_LT(glm::length(torque + reaction_torque), 1e-12 * scale);
}

TEST(WorldForces, ADynamicObjectFallsAsTheIntegratorSays) {
  // semi-implicit Euler from rest: after n steps v = n g dt, z = g dt^2 n (n + 1) / 2
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  World world(def);
  ObjectDef ball;
  ball.dynamic = true;
  ball.pose.position = vec3(1.0, 2.0, 3.0);
  ObjectHandle handle;
  ASSERT_EQ(world.add_object(scenes::ball_shell(50, 0.02), ball, &handle), FRUSTA_OK);
  const double dt = 1.0 / def.rate_hz;
  for (int n = 1; n <= 500; ++n) world.step();
  world.step();  // the snapshot shows the pose the step met: 500 steps moved it
  const ObjectSnapshot& o = world.read().objects[static_cast<size_t>(handle.slot)];
  EXPECT_NEAR(o.pose.position.z, 3.0 - 9.81 * dt * dt * 500 * 501 / 2, 1e-12);
  EXPECT_NEAR(o.linear_velocity.z, -9.81 * dt * 500, 1e-12);
  EXPECT_EQ(o.pose.position.x, 1.0);

  // taken back by the host: at rest where it is put
  ASSERT_EQ(world.set_object_dynamic(handle, false), FRUSTA_OK);
  for (int n = 0; n < 10; ++n) world.step();
  const ObjectSnapshot& still = world.read().objects[static_cast<size_t>(handle.slot)];
  EXPECT_EQ(still.linear_velocity.z, 0.0);
  EXPECT_EQ(still.pose.position.z, o.pose.position.z - 9.81 * dt * dt * 501);
}

TEST(WorldForces, ABoxOnAnOpenPalmIsLiftedCarriedAndTippedOff) {
  const HandModel model = right_hand();
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  World world(def);
  const HandHandle hand = add_hand(world, model);
  // palm up: the hand turned over about its long axis, fingers curled a little
  const glm::dquat up = scenes::about(vec3(1, 0, 0), glm::pi<double>());
  HandState palm_up = scenes::open_hand(vec3(0.0), up);
  for (int f = 1; f < 5; ++f) scenes::set_flexion(palm_up, f, 0.3, 0.3, 0.3);
  double top = 0.0, centre_x = 0.0;  // of the palm spheres, turned over
  for (const Sphere& p : model.palm_spheres) {
    top = std::max(top, -p.center.z + p.radius);
    centre_x += p.center.x / static_cast<double>(model.palm_spheres.size());
  }
  // a 5 cm box of 50 g dropped from 1 mm onto the palm
  const double edge = scenes::test_box_spec("lifted_box").size.x;
  ObjectDef object;
  object.pose.position = vec3(centre_x, 0.0, top + 0.5 * edge + 0.001);
  object.dynamic = true;
  object.mass = 0.05;
  object.inertia = vec3(object.mass * edge * edge / 6);
  object.linear_damping = object.angular_damping = 0.5;  // air, roughly
  object.material.normal_damping = 2.0 * std::sqrt(kDefaultContactStiffness * object.mass);
  ObjectHandle handle;
  ASSERT_EQ(world.add_object(scenes::test_box("lifted_box"), object, &handle), FRUSTA_OK);
  const size_t slot = static_cast<size_t>(handle.slot);
  const vec3 start = object.pose.position;

  // settle 0.5 s, carry up 15 cm and across over 1 s (gently: the carry starts and
  // stops at rest), hold 0.5 s
  const vec3 carry(0.10, 0.05, 0.15);
  double worst_lag = 0.0, weight_sum = 0.0;
  for (int t = 0; t <= 2000; ++t) {
    HandState s = palm_up;
    s.palm_position += carry * smooth((t - 500) / 1000.0);
    world.set_haptic(hand, s);
    world.step();
    const ObjectSnapshot& o = world.read().objects[slot];
    if (t >= 500) {
      worst_lag = std::max(worst_lag, glm::length(o.pose.position - start - carry * smooth((t - 500) / 1000.0)));
    }
    if (t > 1800) weight_sum += o.reaction.force.z;
  }
  // it sinks by its weight on the palm's springs (and the 1 mm it fell), then moves with it
  EXPECT_LT(worst_lag, 0.004) << "the box went with the hand";
  EXPECT_NEAR(weight_sum / 199, object.mass * 9.81, 0.05) << "the hand bears its weight";
  const ObjectSnapshot& held = world.read().objects[slot];
  EXPECT_LT(glm::length(held.linear_velocity), 0.02) << "and it rests there";

  // turn the palm down over 0.3 s: the box falls off
  for (int t = 0; t <= 600; ++t) {
    HandState s = palm_up;
    s.palm_position += carry;
    s.palm_rotation = glm::slerp(up, glm::dquat(1, 0, 0, 0), smooth(t / 300.0));
    world.set_haptic(hand, s);
    world.step();
  }
  const ObjectSnapshot& dropped = world.read().objects[slot];
  EXPECT_LT(dropped.pose.position.z, held.pose.position.z - 0.05);
  EXPECT_LT(dropped.linear_velocity.z, -1.0);
  EXPECT_EQ(world.read().hand(hand)->contact_count, 0);
}

// A ball pinched between thumb and index pads, `pressed` deep each, handed to gravity
// and carried 19 cm over a second; how far it strays from the hand's path, and where
// it ends up.
struct PinchCarry {
  double worst_lag = 0.0;  // metres
  double weight_borne = 0.0;  // mean reaction along +z over the last 0.2 s, newtons
  vec3 end_velocity{0.0};
};

PinchCarry carry_pinched_ball(double mass, double friction, double pressed) {
  const scenes::HandScenario pinch = scenes::ball_pinch(pressed);
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  World world(def);
  const HandHandle hand = add_hand(world, right_hand());
  ObjectDef object = ball_def(pinch.objects[0].pose, mass, 0.015);
  object.material.friction = friction;
  object.material.normal_damping = 5.0;
  ObjectHandle handle;
  EXPECT_EQ(world.add_object(pinch.trees[0], object, &handle), FRUSTA_OK);
  const size_t slot = static_cast<size_t>(handle.slot);
  // the pinch closes while the host holds the ball, then lets go of it
  for (int32_t t = 0; t < pinch.steps; ++t) {
    world.set_haptic(hand, pinch.haptic(t));
    world.step();
  }
  EXPECT_EQ(world.set_object_dynamic(handle, true), FRUSTA_OK);
  world.step();
  const vec3 start = world.read().objects[slot].pose.position;
  const vec3 carry(0.10, 0.05, 0.15);
  PinchCarry result;
  for (int t = 0; t <= 2000; ++t) {
    HandState s = pinch.held;
    s.palm_position += carry * smooth((t - 500) / 1000.0);
    world.set_haptic(hand, s);
    world.step();
    const ObjectSnapshot& o = world.read().objects[slot];
    result.worst_lag = std::max(
        result.worst_lag, glm::length(o.pose.position - start - carry * smooth((t - 500) / 1000.0)));
    if (t > 1800) result.weight_borne += o.reaction.force.z / 200.0;
    result.end_velocity = o.linear_velocity;
  }
  return result;
}

TEST(WorldForces, APinchedBallIsCarriedWhileMuTimesTheSqueezeBearsItsWeight) {
  // 3 mm deep a pad at 400 N/m squeezes with about 1.2 N (more where a second segment
  // touches): at mu 0.8 that bears 50 g, not 200 g
  const PinchCarry held = carry_pinched_ball(0.05, 0.8, 0.003);
  EXPECT_LT(held.worst_lag, 0.005) << "the ball went with the hand";
  EXPECT_NEAR(held.weight_borne, 0.05 * 9.81, 0.1);
  EXPECT_LT(glm::length(held.end_velocity), 0.05);

  const PinchCarry heavy = carry_pinched_ball(0.2, 0.8, 0.003);
  EXPECT_GT(heavy.worst_lag, 0.5) << "too heavy for the squeeze: it slips out and falls";
  EXPECT_LT(heavy.end_velocity.z, -1.0);

  const PinchCarry slippery = carry_pinched_ball(0.05, 0.05, 0.003);
  EXPECT_GT(slippery.worst_lag, 0.5) << "too slippery for the squeeze";
}

// Grasp under jitter (issue 20): a host on a busy machine stamps its samples (noise
// 0.3 ms) and delivers them late, in bursts after stalls of 5, 10, 20 and 50 ms every
// 150 ms; the world steps on its own clock (the test steps it: deterministic). The
// hand closes on an object, the object is handed to gravity, settles for 0.5 s, is
// carried 15 cm up (and 11 cm across) over 1 s, and held 0.5 s.
struct JitterCarry {
  double worst_lag = 0.0;  // metres, from where the played hand's path puts it
  double end_error = 0.0;  // metres, from the start plus the carry, after the hold
  int64_t late_steps = 0;  // steps whose input was extrapolated or held
};

constexpr int64_t kSettle = 500, kCarry = 1000, kHold = 500;
const vec3 kCarried(0.10, 0.05, 0.15);

// closing: the hand over the first `closing` steps (ms); then held at `held`, carried
JitterCarry carry_under_jitter(const std::function<HandState(double)>& closing, int64_t closing_steps,
                               const HandState& held, std::shared_ptr<const TreeFile> tree,
                               ObjectDef object, uint32_t seed) {
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  World world(def);
  const HandHandle hand = add_hand(world, right_hand());
  const bool dynamic_from_start = object.dynamic;
  object.dynamic = false;
  ObjectHandle handle;
  EXPECT_EQ(world.add_object(std::move(tree), object, &handle), FRUSTA_OK);
  const size_t slot = static_cast<size_t>(handle.slot);
  // the played input reaches the closed hand input_delay after the script does
  const int64_t release = dynamic_from_start ? 1 : closing_steps + 20;
  const int64_t carry_from = release + kSettle, end = carry_from + kCarry + kHold;
  auto script = [&](double t) {
    const double ms = t * 1e3;
    if (ms < static_cast<double>(closing_steps)) return closing(ms);
    HandState s = held;
    s.palm_position += kCarried * smooth((ms - static_cast<double>(carry_from)) / kCarry);
    return s;
  };
  // seed 0: a host on an idle machine (no stall, no noise), the control
  const scenes::JitteryHost host(
      seed == 0 ? std::vector<scenes::HostStall>{}
                : scenes::JitteryHost::stall_cycle(release + 100 + 7 * seed, end, 150),
      seed == 0 ? 0.0 : 0.0003, seed);
  std::vector<int64_t> samples;
  JitterCarry result;
  vec3 start(0.0);
  for (int64_t n = 1; n <= end; ++n) {
    host.delivered_before(n, &samples);
    for (int64_t j : samples) {
      const double t = host.stamp(j);
      EXPECT_EQ(world.set_haptic_at(hand, script(t), static_cast<int64_t>(std::llround(t * 1e9))),
                FRUSTA_OK);
    }
    if (n == release) {
      EXPECT_EQ(world.set_object_dynamic(handle, true), FRUSTA_OK);
    }
    world.step();
    const WorldSnapshot& snap = world.read();
    result.late_steps += snap.hand(hand)->input_late ? 1 : 0;
    const vec3 at = snap.objects[slot].pose.position;
    if (n == carry_from) start = at;
    if (n > carry_from) {
      // where the played hand (input_delay behind) has carried it
      const double played = static_cast<double>(n - carry_from) - def.input_delay * 1e3;
      result.worst_lag = std::max(result.worst_lag, glm::length(at - start - kCarried * smooth(played / kCarry)));
    }
    if (n == end) result.end_error = glm::length(at - start - kCarried);
  }
  return result;
}

TEST(WorldForces, AGraspUnderHostJitterIsCarriedTheFullDistanceInEveryRun) {
  // the marble pinched (the demo's: 50 g, mu 0.8)
  const scenes::HandScenario pinch = scenes::ball_pinch(0.003);
  ObjectDef marble;
  marble.pose = pinch.objects[0].pose;
  marble.mass = 0.05;
  marble.inertia = vec3(0.4 * marble.mass * 0.015 * 0.015);
  marble.linear_damping = marble.angular_damping = 0.5;
  marble.material.friction = 0.8;
  // the demo's marble: damped along and across its contacts, so a hand's jitter does not
  // kick it loose (frusta_object_def.tangential_damping)
  marble.material.normal_damping = 9.0;
  marble.material.tangential_damping = 10.0;
  auto pinch_at = [&](double ms) {
    const int32_t i = static_cast<int32_t>(std::floor(ms));
    return scenes::mix(pinch.haptic(i), pinch.haptic(i + 1), ms - std::floor(ms));
  };
  // a 200 g box of 5 cm on the palm, turned up (as ABoxOnAnOpenPalm... carries 50 g)
  const HandModel model = right_hand();
  const glm::dquat up = scenes::about(vec3(1, 0, 0), glm::pi<double>());
  HandState palm_up = scenes::open_hand(vec3(0.0), up);
  for (int f = 1; f < 5; ++f) scenes::set_flexion(palm_up, f, 0.3, 0.3, 0.3);
  double top = 0.0, centre_x = 0.0;
  for (const Sphere& p : model.palm_spheres) {
    top = std::max(top, -p.center.z + p.radius);
    centre_x += p.center.x / static_cast<double>(model.palm_spheres.size());
  }
  const double edge = scenes::test_box_spec("lifted_box").size.x;
  ObjectDef box;
  box.pose.position = vec3(centre_x, 0.0, top + 0.5 * edge + 0.001);
  box.dynamic = true;
  box.mass = 0.2;
  box.inertia = vec3(box.mass * edge * edge / 6);
  box.linear_damping = box.angular_damping = 0.5;
  box.material.normal_damping = 2.0 * std::sqrt(kDefaultContactStiffness * box.mass);
  // a 100 g ball of 4 cm radius under the palm, in the power grasp of scenes::ball_grasp:
  // the fingers push it far harder than the palm and thumb do (tens of newtons over), and
  // the grasp condition (forces/grasp.h) holds it
  const std::shared_ptr<const TreeFile> ball_tree = scenes::sample_tree("ball");
  const scenes::HandScenario power = scenes::ball_grasp(ball_tree);
  const ObjectDef ball = ball_def(power.objects[0].pose, 0.1, 0.04);
  auto power_at = [&](double ms) {
    const int32_t i = static_cast<int32_t>(std::floor(ms));
    return scenes::mix(power.haptic(i), power.haptic(i + 1), ms - std::floor(ms));
  };
  for (uint32_t seed = 0; seed <= 8; ++seed) {
    if (!scenes::scenario_runs(seed)) continue;
    const JitterCarry m = carry_under_jitter(pinch_at, pinch.steps, pinch.held, pinch.trees[0], marble, seed);
    EXPECT_LT(m.worst_lag, 0.01) << "marble, run " << seed << ": it stayed in the pinch";
    EXPECT_LT(m.end_error, 0.01) << "marble, run " << seed << ": carried the full distance";
    if (seed > 0) {
      EXPECT_GT(m.late_steps, 100) << "the 20 and 50 ms stalls outran the delay";
    }
    const JitterCarry b = carry_under_jitter([&](double) { return palm_up; }, 0, palm_up,
                                             scenes::test_box("lifted_box"), box, seed);
    EXPECT_LT(b.worst_lag, 0.01) << "200 g box, run " << seed;
    EXPECT_LT(b.end_error, 0.01) << "200 g box, run " << seed;
    const JitterCarry p = carry_under_jitter(power_at, power.steps, power.held, ball_tree, ball, seed);
    EXPECT_LT(p.worst_lag, 0.01) << "ball in a power grasp, run " << seed;
    EXPECT_LT(p.end_error, 0.01) << "ball in a power grasp, run " << seed;
    std::printf("run %u: worst lag / end error, mm: marble %.2f / %.2f, box %.2f / %.2f, "
                "power-grasped ball %.2f / %.2f; late steps %lld\n",
                seed, 1e3 * m.worst_lag, 1e3 * m.end_error, 1e3 * b.worst_lag, 1e3 * b.end_error,
                1e3 * p.worst_lag, 1e3 * p.end_error,
                static_cast<long long>(m.late_steps));
  }
}

// Issue 20, Build 4: a ball under the palm in a power grasp (its fingers push it tens of
// newtons harder than palm and thumb) is held (forces/grasp.h): lifted, carried and turned
// rigidly with the hand, and let go when the hand opens, falling from there without being
// flung by the fingers' last pushes.
TEST(WorldForces, APowerGraspedBallIsCarriedTurnedAndLetGoWhenTheHandOpens) {
  const std::shared_ptr<const TreeFile> tree = scenes::sample_tree("ball");
  const scenes::HandScenario power = scenes::ball_grasp(tree);
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  World world(def);
  const HandHandle hand = add_hand(world, right_hand());
  ObjectHandle handle;
  ASSERT_EQ(world.add_object(tree, ball_def(power.objects[0].pose, 0.1, 0.04), &handle), FRUSTA_OK);
  const size_t slot = static_cast<size_t>(handle.slot);
  for (int32_t t = 0; t < power.steps; ++t) {  // the host holds it while the hand closes
    world.set_haptic(hand, power.haptic(t));
    world.step();
  }
  ASSERT_EQ(world.set_object_dynamic(handle, true), FRUSTA_OK);
  // lifted 15 cm, carried 10 cm and turned a quarter about the forearm over 1 s
  const vec3 carry(0.0, 0.10, 0.15);
  const glm::dquat turn = scenes::about(vec3(1, 0, 0), 0.5 * glm::pi<double>());
  auto hand_at = [&](double u) {
    HandState s = power.held;
    s.palm_position += carry * smooth(u);
    s.palm_rotation = glm::slerp(glm::dquat(1, 0, 0, 0), turn, smooth(u));
    return s;
  };
  // the ball in the palm's frame, from the first held step on
  vec3 in_palm(0.0);
  double worst_slip = 0.0, worst_turn = 0.0;
  for (int t = 0; t <= 1200; ++t) {
    world.set_haptic(hand, hand_at(t / 1000.0));
    world.step();
    const ObjectSnapshot& o = world.read().objects[slot];
    // taken hold of at the end of the first step; a snapshot shows it where that step's
    // hand met it, which the step before put in its palm
    if (t == 0) continue;
    ASSERT_EQ(o.held_by, hand.slot) << "step " << t << ": held from the first";
    const HandState s = hand_at((t - 1) / 1000.0);
    const glm::dmat3 palm = glm::mat3_cast(s.palm_rotation);
    const vec3 here = glm::transpose(palm) * (o.pose.position - s.palm_position);
    if (t == 1) in_palm = here;
    worst_slip = std::max(worst_slip, glm::length(here - in_palm));
    // the ball turns with the palm: its x axis (from the start's identity) follows palm's
    worst_turn = std::max(worst_turn, glm::length(o.pose.rotation[0] - palm[0]));
  }
  EXPECT_LT(worst_slip, 1e-9) << "rigid in the (played) palm";
  EXPECT_LT(worst_turn, 1e-9) << "turned with the palm";
  // the hand opens over 250 ms where it is
  const HandState closed = hand_at(1.0);
  HandState open = scenes::open_hand(closed.palm_position, closed.palm_rotation);
  int let_go = -1;
  vec3 at_release(0.0), end(0.0);
  double fastest = 0.0;
  for (int t = 0; t < 600; ++t) {
    world.set_haptic(hand, scenes::mix(closed, open, std::min(1.0, t / 250.0)));
    world.step();
    const ObjectSnapshot& o = world.read().objects[slot];
    if (let_go < 0 && o.held_by < 0) {
      let_go = t;
      at_release = o.pose.position;
    }
    if (let_go >= 0 && t - let_go <= 100) {
      // free fall reaches 1 m/s in 0.1 s; the hand opening where it is adds little
      fastest = std::max(fastest, glm::length(o.linear_velocity));
    }
    end = o.pose.position;
  }
  std::printf("let go %d ms into the opening; fastest in the next 0.1 s %.3f m/s; fell %.1f mm, "
              "%.1f mm sideways\n", let_go, fastest, 1e3 * (at_release.z - end.z),
              1e3 * glm::length(vec3(end.x - at_release.x, end.y - at_release.y, 0.0)));
  ASSERT_GE(let_go, 0) << "the opened hand lets go";
  // (with the fingers' pushes back at once: 1.5 m/s, 15 cm sideways)
  EXPECT_LT(fastest, 1.2) << "not flung";
  EXPECT_LT(glm::length(vec3(end.x - at_release.x, end.y - at_release.y, 0.0)), 0.05) << "not flung";
  EXPECT_GT(at_release.z - end.z, 0.05) << "it falls";
}

TEST(WorldForces, BadObjectsAreRefusedAndChangeNothing) {
  World world(WorldDef{});
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(50, 0.02);
  ObjectDef def;
  ObjectHandle handle{-1, 0};
  auto refused = [&](const ObjectDef& d, frusta_result code) {
    EXPECT_EQ(world.add_object(ball, d, &handle), code) << frusta::last_error_message();
    EXPECT_EQ(handle.slot, -1);
  };
  ObjectDef bad = def;
  bad.mass = 0.0;
  refused(bad, FRUSTA_ERROR_OUT_OF_RANGE);
  bad = def;
  bad.pose.position.x = std::nan("");
  refused(bad, FRUSTA_ERROR_NOT_FINITE);
  bad = def;
  bad.pose.rotation[0][0] = 2.0;  // a scale, not a rotation
  refused(bad, FRUSTA_ERROR_OUT_OF_RANGE);
  bad = def;
  bad.pose.rotation = glm::dmat3(-1.0);  // a reflection
  refused(bad, FRUSTA_ERROR_OUT_OF_RANGE);
  bad = def;
  bad.material.friction = -0.1;
  refused(bad, FRUSTA_ERROR_OUT_OF_RANGE);
  bad = def;
  bad.inertia.y = std::numeric_limits<double>::infinity();
  refused(bad, FRUSTA_ERROR_NOT_FINITE);
  world.step();
  for (const ObjectSnapshot& o : world.read().objects) EXPECT_FALSE(o.present);

  ASSERT_EQ(world.add_object(ball, def, &handle), FRUSTA_OK);
  RigidPose nowhere;
  nowhere.position.z = 1e7;
  EXPECT_EQ(world.set_object_pose(handle, nowhere), FRUSTA_ERROR_OUT_OF_RANGE);
  world.step();
  EXPECT_EQ(world.read().objects[static_cast<size_t>(handle.slot)].pose.position, vec3(0.0));
}

}  // namespace
}  // namespace frusta
