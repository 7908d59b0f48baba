// SPDX-License-Identifier: MIT
// The world as a host sees it: commands at step boundaries, the hands it solves equal
// to standalone solvers, trees held while used, nothing allocated in a steady step, and
// a reader on another thread that never sees a torn snapshot.
#include "runtime/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/thread_priority.h"
#include "core/validate.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/hand_scenarios.h"
#include "allocation_counter.h"

namespace frusta {
namespace {

HandModel right_hand() { return make_hand_model(default_hand_def()); }

HandHandle add_hand(World& world, const HandModel& model) {
  HandHandle hand;
  EXPECT_EQ(world.add_hand(model, &hand), FRUSTA_OK);
  return hand;
}

// made here rather than loaded: the ThreadSanitizer build has no baked samples
std::shared_ptr<const TreeFile> ball_tree() {
  static const std::shared_ptr<const TreeFile> tree = scenes::ball_shell(500, 0.04);
  return tree;
}

const RigidPose kBallPose{vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)};

// A right hand and the grasp's ball at kBallPose, in `world`.
void add_hand_and_ball(World& world, const scenes::HandScenario& grasp, HandHandle* hand, ObjectHandle* ball) {
  *hand = add_hand(world, right_hand());
  ASSERT_EQ(world.add_object(grasp.trees[0], kBallPose, ball), FRUSTA_OK);
}

TEST(World, SolvesEachHandExactlyAsAStandaloneSolver) {
  const scenes::HandScenario grasp = scenes::ball_grasp(ball_tree());
  World world(WorldDef{});
  HandHandle hand;
  ObjectHandle ball;
  ASSERT_NO_FATAL_FAILURE(add_hand_and_ball(world, grasp, &hand, &ball));
  HandSolver alone(right_hand(), SolverParams{});
  for (int32_t t = 0; t < grasp.steps; ++t) {
    world.set_haptic(hand, grasp.haptic(t));
    world.step();
    ASSERT_EQ(alone.step(grasp.haptic(t), grasp.objects.data(), 1, nullptr), FRUSTA_OK);
  }
  const WorldSnapshot& s = world.read();
  EXPECT_EQ(s.step, static_cast<uint64_t>(grasp.steps));
  for (size_t j = 0; j < alone.graphic().angles.size(); ++j)
    EXPECT_EQ(s.hand(hand)->graphic.angles[j], alone.graphic().angles[j]) << "joint " << j;
  ASSERT_EQ(s.hand(hand)->contact_count, static_cast<int32_t>(alone.contacts().size()));
  for (int32_t i = 0; i < s.hand(hand)->contact_count; ++i)
    EXPECT_EQ(s.hand(hand)->contacts[static_cast<size_t>(i)].object, ball.slot) << "contacts name the slot";
}

TEST(World, CommandsTakeEffectAtTheNextStepAndStaleHandlesAreRefused) {
  WorldDef def;
  def.max_objects = 3;
  World world(def);
  const HandHandle hand = add_hand(world, right_hand());
  HandState closed = scenes::open_hand();
  for (int f = 1; f < 5; ++f) scenes::set_flexion(closed, f, 1.6, 1.6, 1.6);
  world.set_haptic(hand, closed);
  ObjectHandle ball;
  ASSERT_EQ(world.add_object(ball_tree(), kBallPose, &ball), FRUSTA_OK);
  EXPECT_EQ(world.read().step, 0u) << "nothing happens before a step";
  // the first step places the hand; the fingers close onto the ball over the next ones
  for (int i = 0; i < 50; ++i) world.step();
  EXPECT_GT(world.read().hand(hand)->contact_count, 0);
  ASSERT_EQ(world.remove_object(ball), FRUSTA_OK);
  EXPECT_EQ(world.remove_object(ball), FRUSTA_ERROR_STALE_ID) << "removed twice";
  EXPECT_EQ(world.set_object_pose(ball, kBallPose), FRUSTA_ERROR_STALE_ID);
  world.step();
  const WorldSnapshot& s = world.read();
  EXPECT_EQ(s.hand(hand)->contact_count, 0) << "the ball is gone";
  // with nothing left, the hand closes to its haptic angles (clamped) at once
  HandState clamped = closed;
  clamp_to_limits(right_hand(), clamped);
  for (size_t j = 0; j < clamped.angles.size(); ++j)
    EXPECT_EQ(s.hand(hand)->graphic.angles[j], clamped.angles[j]);
  // capacity: three slots
  ObjectHandle o[3];
  for (ObjectHandle& h : o) ASSERT_EQ(world.add_object(ball_tree(), RigidPose{vec3(1.0), glm::dmat3(1.0)}, &h), FRUSTA_OK);
  ObjectHandle extra;
  EXPECT_EQ(world.add_object(ball_tree(), RigidPose{vec3(2.0), glm::dmat3(1.0)}, &extra), FRUSTA_ERROR_CAPACITY);
  EXPECT_NE(o[0].generation, 0u);
}

TEST(World, HoldsATreeUntilAStepHasLetGoOfIt) {
  World world(WorldDef{});
  add_hand(world, right_hand());
  std::weak_ptr<const TreeFile> watch;
  ObjectHandle box;
  {
    auto tree = std::make_shared<TreeFile>(*ball_tree());
    watch = tree;
    ASSERT_EQ(world.add_object(std::move(tree), RigidPose{vec3(0.5, 0, 0), glm::dmat3(1.0)}, &box), FRUSTA_OK);
  }
  world.step();
  EXPECT_FALSE(watch.expired()) << "the world holds it";
  ASSERT_EQ(world.remove_object(box), FRUSTA_OK);
  world.read();
  EXPECT_FALSE(watch.expired()) << "no step has applied the removal: the stepping thread may still use it";
  world.step();
  world.read();  // the host releases retired trees
  EXPECT_TRUE(watch.expired());
}

TEST(World, AnObjectPutInsideAHandIsIgnoredByItUntilTheyPart) {
  // a ball put where the hand's fingers already are: the hand is not trapped or shoved,
  // it goes on as if the ball were not there; once the hand has left the ball, the ball
  // is solid to it again
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  const HandState open = scenes::open_hand();
  world.set_haptic(hand, open);
  world.step();
  const HandState before = world.read().hand(hand)->graphic;
  ObjectHandle ball;
  const RigidPose through_fingers{vec3(0.15, 0.0, 0.0), glm::dmat3(1.0)};  // the fingers run through it
  ASSERT_EQ(world.add_object(ball_tree(), through_fingers, &ball), FRUSTA_OK);
  for (int t = 0; t < 20; ++t) {
    world.set_haptic(hand, open);
    world.step();
  }
  const HandSnapshot& inside = *world.read().hand(hand);
  EXPECT_EQ(inside.contact_count, 0);
  EXPECT_EQ(inside.graphic.palm_position, before.palm_position) << "not shoved out";
  EXPECT_EQ(world.read().objects[static_cast<size_t>(ball.slot)].reaction.force, vec3(0.0));
  EXPECT_EQ(inside.ignored_objects, 1);
  EXPECT_EQ(world.read().object(ball)->ignored_by, uint64_t{1} << hand.slot)
      << "the snapshot says which hands ignore it";

  // the hand backs off 20 cm, then comes back: now the ball stops it
  HandState away = open;
  away.palm_position.x = -0.2;
  for (int t = 0; t < 200; ++t) {
    world.set_haptic(hand, scenes::mix(open, away, t / 100.0));
    world.step();
  }
  for (int t = 0; t < 300; ++t) {
    world.set_haptic(hand, scenes::mix(away, open, t / 200.0));
    world.step();
  }
  const HandSnapshot& back = *world.read().hand(hand);
  EXPECT_GT(back.contact_count, 0) << "the ball is solid again";
  EXPECT_EQ(back.ignored_objects, 0);
  EXPECT_EQ(world.read().object(ball)->ignored_by, 0u);
  HandPose pose;
  forward_kinematics(right_hand(), back.graphic, pose);
  const SolverObject placed{&ball_tree()->tree, through_fingers};
  EXPECT_LE(scenes::deepest_penetration(right_hand(), pose, {placed}), 1e-5)
      << "the hand stays out of it (the fingers bend around it)";
}

// Refused where it enters, never taken and dropped later: an input set_haptic accepts
// is an input the step uses.
TEST(World, BadHapticInputIsRefusedAtTheDoorAndLeavesTheGraphicHand) {
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  HandState h = scenes::open_hand();
  h.angles[5] = 0.3;
  world.set_haptic(hand, h);
  world.step();
  const HandState before = world.read().hand(hand)->graphic;
  h.angles[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(world.set_haptic(hand, h), FRUSTA_ERROR_NOT_FINITE);
  h.angles[5] = 1.01 * kMaxJointAngle;
  EXPECT_EQ(world.set_haptic(hand, h), FRUSTA_ERROR_OUT_OF_RANGE);
  h.angles[5] = 0.3;
  h.palm_rotation = glm::dquat(0.1, 0.0, 0.0, 0.0);
  EXPECT_EQ(world.set_haptic(hand, h), FRUSTA_ERROR_OUT_OF_RANGE);
  world.step();
  const WorldSnapshot& s = world.read();
  EXPECT_EQ(s.rejected_inputs, 0);
  EXPECT_EQ(s.hand(hand)->graphic.angles[5], before.angles[5]);
  EXPECT_EQ(world.set_haptic({1, hand.generation}, scenes::open_hand()), FRUSTA_ERROR_STALE_ID)
      << "one hand only";
  EXPECT_EQ(world.set_haptic({-1, hand.generation}, scenes::open_hand()), FRUSTA_ERROR_STALE_ID);
  EXPECT_EQ(world.set_haptic({hand.slot, hand.generation + 1}, scenes::open_hand()),
            FRUSTA_ERROR_STALE_ID);
}

// The rule lets a quaternion's norm lie in [0.5, 2]; the world keeps it unit from the
// door on, so the inputs it interpolates between (slerp wants unit ones) stay rotations.
TEST(World, HapticRotationsAreUnitFromTheDoorOn) {
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  HandState h = scenes::open_hand();
  h.palm_rotation = 2.0 * glm::angleAxis(0.4, vec3(0.0, 0.0, 1.0));
  ASSERT_EQ(world.set_haptic(hand, h), FRUSTA_OK);
  world.step();
  h.palm_rotation = 0.5 * glm::angleAxis(-0.4, vec3(0.0, 1.0, 0.0));
  ASSERT_EQ(world.set_haptic(hand, h), FRUSTA_OK);
  world.step();
  const WorldSnapshot& s = world.read();
  EXPECT_NEAR(glm::length(s.hand(hand)->haptic.palm_rotation), 1.0, 1e-15);
  EXPECT_NEAR(glm::length(s.hand(hand)->graphic.palm_rotation), 1.0, 1e-15);
}

// Issue 21's broad phase: a hand grasping a ball among 400 props spread over a room
// (one put there from across the room, one falling, half removed midway, one moved
// nearer) meets exactly what it meets with the ball alone, bit for bit, and the
// room's steps allocate nothing.
TEST(World, FarObjectsChangeNothingTheHandMeets) {
  const scenes::HandScenario grasp = scenes::ball_grasp(ball_tree());
  World alone(WorldDef{});
  HandHandle hand_alone;
  ObjectHandle ball_alone;
  ASSERT_NO_FATAL_FAILURE(add_hand_and_ball(alone, grasp, &hand_alone, &ball_alone));

  WorldDef def;
  def.max_objects = 512;
  def.command_capacity = 1024;
  def.gravity = vec3(0.0, 0.0, -9.81);  // for the falling prop; the ball is kinematic
  World room(def);
  const HandHandle hand = add_hand(room, right_hand());
  ObjectHandle ball;
  ASSERT_EQ(room.add_object(grasp.trees[0], RigidPose{vec3(4.0, 4.0, 1.0), glm::dmat3(1.0)}, &ball),
            FRUSTA_OK);
  std::vector<ObjectHandle> props(400);
  for (int k = 0; k < 400; ++k) {
    // 1 m apart, none nearer the hand than 0.7 m
    const vec3 at(-4.5 + k % 10, -4.5 + (k / 10) % 10, -0.6 + 0.4 * (k / 100));
    ASSERT_EQ(room.add_object(ball_tree(), RigidPose{at, glm::dmat3(1.0)}, &props[static_cast<size_t>(k)]),
              FRUSTA_OK);
  }
  ASSERT_EQ(room.set_object_pose(ball, kBallPose), FRUSTA_OK);  // across the room, before any step
  ASSERT_EQ(room.set_object_dynamic(props[399], true), FRUSTA_OK);  // falls through the room
  ASSERT_EQ(ball.slot, ball_alone.slot);

  int64_t allocations = 0;
  for (int32_t t = 0; t < grasp.steps + 100; ++t) {
    const HandState haptic = grasp.haptic(std::min(t, grasp.steps - 1));
    if (t == 100) {
      for (int k = 0; k < 200; ++k) {
        ASSERT_EQ(room.remove_object(props[static_cast<size_t>(2 * k)]), FRUSTA_OK);
      }
    }
    if (t == 150) {
      ASSERT_EQ(room.set_object_pose(props[1], RigidPose{vec3(0.1, 0.6, -0.058), glm::dmat3(1.0)}), FRUSTA_OK);
    }
    alone.set_haptic(hand_alone, haptic);
    room.set_haptic(hand, haptic);
    alone.step();
    const int64_t before = allocation_count();
    room.step();
    if (t > 200) allocations += allocation_count() - before;
    const HandSnapshot& a = *alone.read().hand(hand_alone);
    const WorldSnapshot& r = room.read();
    const HandSnapshot& b = *r.hand(hand);
    ASSERT_EQ(b.graphic.palm_position, a.graphic.palm_position) << "step " << t;
    ASSERT_EQ(b.graphic.palm_rotation, a.graphic.palm_rotation) << "step " << t;
    ASSERT_EQ(b.graphic.angles, a.graphic.angles) << "step " << t;
    ASSERT_EQ(b.contact_count, a.contact_count) << "step " << t;
    for (int32_t i = 0; i < std::min(b.contact_count, def.max_contacts_per_hand); ++i) {
      const size_t k = static_cast<size_t>(i);
      ASSERT_EQ(b.contacts[k].object, ball.slot);
      ASSERT_EQ(b.contacts[k].distance, a.contacts[k].distance) << "step " << t << " contact " << i;
    }
    const ObjectSnapshot& held = r.objects[static_cast<size_t>(ball.slot)];
    ASSERT_EQ(held.reaction.force, alone.read().objects[static_cast<size_t>(ball_alone.slot)].reaction.force);
    ASSERT_EQ(r.objects[static_cast<size_t>(props[1].slot)].reaction.force, vec3(0.0));
  }
  EXPECT_GT(room.read().hand(hand)->contact_count, 0) << "the hand holds the ball";
  EXPECT_LT(room.read().objects[static_cast<size_t>(props[399].slot)].pose.position.z, 0.5)
      << "the dynamic prop fell from 0.6 m";
  EXPECT_EQ(allocations, 0);
}

TEST(World, TwoHandsAndTwentyObjectsStepWithoutAllocating) {
  World world(WorldDef{});
  const HandHandle right = add_hand(world, right_hand());
  HandDef left_def = default_hand_def();
  left_def.side = FRUSTA_HAND_LEFT;
  const HandHandle left = add_hand(world, make_hand_model(left_def));
  ObjectHandle handles[20];
  for (int k = 0; k < 20; ++k) {
    const vec3 at = k == 0 ? kBallPose.position : vec3(0.6 * std::cos(0.3 * k), 0.6 * std::sin(0.3 * k), 0.0);
    ASSERT_EQ(world.add_object(ball_tree(), RigidPose{at, glm::dmat3(1.0)}, &handles[k]),
              FRUSTA_OK);
  }
  HandState closed = scenes::open_hand();
  for (int f = 0; f < 5; ++f) scenes::set_flexion(closed, f, 1.6, 1.6, 1.6);
  HandState far = scenes::open_hand(vec3(0.0, 0.3, 0.0));
  for (int t = 0; t < 300; ++t) {  // warm up: the buffers reach their high-water marks
    world.set_haptic(right, scenes::mix(scenes::open_hand(), closed, t / 250.0));
    world.set_haptic(left, far);
    world.step();
  }
  const int64_t before = allocation_count();
  for (int t = 0; t < 10000; ++t) {
    world.set_haptic(right, closed);
    world.set_haptic(left, far);
    world.step();
  }
  EXPECT_EQ(allocation_count() - before, 0) << "allocations in 10,000 steady steps";
  const WorldSnapshot& s = world.read();
  EXPECT_GT(s.hand(right)->contact_count, 0) << "the right hand holds the ball";
  EXPECT_EQ(s.hand(left)->contact_count, 0);
  EXPECT_GT(s.step_us_p50, 0.0);
}

// The allocations of a world's steps through a grasp of its ball, after the step that
// added them (on this thread); the hand holds the ball at the end.
int64_t grasp_allocations(const WorldDef& def, const scenes::HandScenario& grasp) {
  World world(def);
  HandHandle hand;
  ObjectHandle ball;
  add_hand_and_ball(world, grasp, &hand, &ball);
  world.set_haptic(hand, grasp.haptic(0));
  world.step();  // applies the adds, made on this thread
  const int64_t before = allocation_count();
  for (int32_t t = 1; t < grasp.steps; ++t) {
    world.set_haptic(hand, grasp.haptic(t));
    world.step();
  }
  const int64_t allocations = allocation_count() - before;
  EXPECT_GT(world.read().hand(hand)->contact_count, 0) << "the hand holds the ball";
  return allocations;
}

// Its buffers are made with the hand (HandSolver's reserve): a hand meeting an object for
// the first time allocates on the 1 kHz thread no more than it does in a steady grasp.
// (It had grown them 51 and 74 times over these grasps' first contacts, each a call into
// malloc and the largest a fresh mapping, faulted in page by page.)
TEST(World, AHandsFirstGraspAllocatesNothing) {
  for (int32_t leaves : {0, 10000}) {  // the sample ball, and one of 10^4 leaves
    const scenes::HandScenario grasp =
        scenes::ball_grasp(leaves > 0 ? scenes::ball_shell(leaves, 0.04) : ball_tree());
    EXPECT_EQ(grasp_allocations(WorldDef{}, grasp), 0) << leaves << " leaves";
  }
}

// A denser ball (4 x 10^4 leaves: some 3,000 candidates near the closing hand) outgrows
// the default buffers, which then grow on the stepping thread; a world made for more
// candidates (max_candidates_per_hand) makes them with the hand, and its steps allocate
// nothing.
TEST(World, AHandMadeForMoreCandidatesGraspsADenseBallAllocatingNothing) {
  const scenes::HandScenario grasp = scenes::ball_grasp(scenes::ball_shell(40000, 0.04));
  WorldDef def;
  EXPECT_GT(grasp_allocations(def, grasp), 0) << "the default buffers hold this ball's candidates";
  def.solver.candidate_capacity = 8192;
  EXPECT_EQ(grasp_allocations(def, grasp), 0) << "made for 8,192 candidates";
}

TEST(World, AReaderOnAnotherThreadNeverSeesATornSnapshot) {
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  ObjectHandle ball;
  ASSERT_EQ(world.add_object(ball_tree(), kBallPose, &ball), FRUSTA_OK);
  std::atomic<bool> done{false};
  const scenes::HandScenario grasp = scenes::ball_grasp(ball_tree());
  std::thread stepper([&] {
    for (int32_t t = 0; !done.load(std::memory_order_relaxed); ++t) {
      world.set_haptic(hand, grasp.haptic(t % grasp.steps));
      world.step();
    }
  });
  uint64_t last = 0, reads = 0, bad = 0, distinct = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while ((reads < 1000000 || distinct < 100) && std::chrono::steady_clock::now() < give_up) {
    const WorldSnapshot& s = world.read();
    ++reads;
    const HandSnapshot* h = s.hand(hand);
    bool ok = s.step >= last && (s.step == 0 || (h && h->contact_count >= 0));
    for (int32_t i = 0; ok && h && i < std::min<int32_t>(h->contact_count, 256); ++i)
      ok = h->contacts[static_cast<size_t>(i)].object == ball.slot &&
           std::isfinite(h->contacts[static_cast<size_t>(i)].distance);
    if (h)
      for (double a : h->graphic.angles) ok &= std::isfinite(a);
    bad += !ok;
    distinct += s.step != last;
    last = s.step;
  }
  done = true;
  stepper.join();
  EXPECT_EQ(bad, 0u);
  EXPECT_GE(reads, 1000000u);
  EXPECT_GE(distinct, 100u);
}

TEST(World, TimedSamplesFromAnInputThreadArriveWholeAndInOrder) {
  // an input thread stamps sample i at i * 0.1 ms with palm x = i * 0.1 mm and an angle
  // of i mrad, as fast as it can, while this thread steps the world: whatever a step
  // plays (a sample, between two, past the newest, fading back) keeps x = angle / 10,
  // and x within what was sent (and max_extrapolation past it)
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  constexpr int kSamples = 10000;
  std::atomic<int> sent{0};
  std::thread input([&] {
    for (int i = 1; i <= kSamples; ++i) {
      HandState s = scenes::open_hand(vec3(1e-4 * i, 0.0, 0.0));
      s.angles[5] = 1e-3 * i;
      if (world.set_haptic_at(hand, s, 100'000 * static_cast<int64_t>(i)) == FRUSTA_OK)
        sent.fetch_add(1, std::memory_order_relaxed);
    }
  });
  int64_t bad = 0, steps = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while ((sent.load(std::memory_order_relaxed) < kSamples || steps < 2000) &&
         std::chrono::steady_clock::now() < give_up) {
    world.step();
    ++steps;
    const HandSnapshot* h = world.read().hand(hand);
    if (!h || !h->solved) continue;
    const double x = h->haptic.palm_position.x;
    bad += std::fabs(x - 0.1 * h->haptic.angles[5]) > 1e-9 || x < -1e-12 ||
           x > 1.0 + WorldDef{}.max_extrapolation + 1e-9;
  }
  input.join();
  EXPECT_EQ(sent.load(), kSamples) << "every sample in time order is taken";
  EXPECT_EQ(bad, 0) << "of " << steps << " steps";
}

TEST(World, TheWorldsSolverSettingsAreCheckedAgainstEachHand) {
  WorldDef def;
  def.solver.prediction_margin = 0.05;  // more than a finger's radius
  World bad(def);
  HandHandle hand;
  EXPECT_EQ(bad.add_hand(right_hand(), &hand), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("prediction_margin"), std::string::npos);
  EXPECT_FALSE(bad.hand_is_live({0, 1})) << "nothing was added";
}

TEST(World, ItsOwnThreadStepsItUntilStoppedAndTheHostMayNotStepMeanwhile) {
  World world(WorldDef{});
  const HandHandle hand = add_hand(world, right_hand());
  world.set_haptic(hand, scenes::open_hand());
  EXPECT_EQ(world.start(0.0, 0.0), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(world.start(1000.0, 5000.0), FRUSTA_ERROR_OUT_OF_RANGE) << "a spin longer than the period";
  ASSERT_EQ(world.start(1000.0, 100.0), FRUSTA_OK);
  EXPECT_TRUE(world.running());
  EXPECT_EQ(world.start(1000.0, 100.0), FRUSTA_ERROR_WRONG_STATE);
  EXPECT_EQ(world.step(), FRUSTA_ERROR_WRONG_STATE);
  // wait (bounded) for the thread to step; how fast is a benchmark's business, not a test's
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (world.read().step < 20 && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const uint64_t seen = world.read().step;
  EXPECT_GE(seen, 20u);
  world.stop();
  EXPECT_FALSE(world.running());
  const uint64_t stopped = world.read().step;
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(world.read().step, stopped) << "no step after stop()";
  EXPECT_EQ(world.step(), FRUSTA_OK) << "the host may step it again";
  EXPECT_EQ(world.read().step, stopped + 1);
}

// The own thread asks for real-time priority when its def says so and reports what the
// system granted: whatever a thread of this process is granted (root or an rtprio limit
// grant it; a plain user is refused), never more.
TEST(World, ItsOwnThreadRunsAtRealTimePriorityWhereGrantedAndSaysSo) {
  bool granted = false;
  std::thread probe([&granted] { granted = raise_to_realtime_priority(); });
  probe.join();
  for (const bool asked : {true, false}) {
    WorldDef def;
    def.realtime_priority = asked;
    World world(def);
    ASSERT_EQ(world.start(), FRUSTA_OK);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (world.read().step < 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_GE(world.read().step, 2u);
    EXPECT_EQ(world.read().realtime, asked && granted) << "asked " << asked << ", granted " << granted;
    world.stop();
    EXPECT_EQ(world.step(), FRUSTA_OK);
    EXPECT_FALSE(world.read().realtime) << "the host's steps run on its thread";
  }
}

}  // namespace
}  // namespace frusta
