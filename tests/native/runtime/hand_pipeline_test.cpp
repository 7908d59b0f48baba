// SPDX-License-Identifier: MIT
// One hand's step, driven through its port as the world drives it, with no thread and
// no clock: what input a step on the world's own thread solves. A glove's unstamped
// samples are solved newest first, as they are (the user feels every period of delay);
// a host's are played input_delay behind, from the jitter buffer; and the feed a step
// publishes names the newest input it had, so a device can tell which sample a command
// answers.
#include "runtime/hand_pipeline.h"

#include <gtest/gtest.h>

#include <memory>

#include "devices/glove_calibration.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "runtime/world.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"

namespace frusta {
namespace {

constexpr int64_t kPeriodNs = 1'000'000;
constexpr int32_t kIndexFlexion1 = FRUSTA_JOINTS_PER_FINGER + 1;

struct OneHand {
  OneHand() : model(make_hand_model(default_hand_def())), port(0, 1000.0), scene(4) {
    port.open(1);
    pipeline = std::make_unique<HandPipeline>(model, SolverParams{}, 64, 4, 0, port);
  }
  // a step on the world's own thread: its time far past the samples' (played input_delay
  // behind it, that is still later than all of them), or far before them
  HandSnapshot& step(int64_t play_ns, uint64_t number) {
    HandStepContext context;
    context.dt = 1e-3;
    context.paced = true;
    context.play_ns = play_ns;
    context.max_extrapolation_ns = 40 * kPeriodNs;
    context.max_contacts = 64;
    HandSnapshot& snap = pipeline->snapshot(static_cast<int>(number % 3));
    EXPECT_TRUE(pipeline->step(context, scene, snap));
    pipeline->publish_feed(snap, number, 0);
    return snap;
  }
  // the index curled this far: one sample
  static HandState curled(double flexion) {
    HandState s = scenes::open_hand();
    s.angles[kIndexFlexion1] = flexion;
    return s;
  }
  HandModel model;
  HandPort port;
  SceneObjects scene;
  std::unique_ptr<HandPipeline> pipeline;
};

TEST(handPipeline, AGlovesUntimedSamplesAreSolvedNewestFirstWhateverTheStepsTime) {
  OneHand hand;
  ASSERT_EQ(hand.port.claim_for_device(), FRUSTA_OK);
  for (int i = 1; i <= 5; ++i)
    ASSERT_EQ(hand.port.set_input(OneHand::curled(0.1 * i), HandPort::Driver::kDevice, 1), FRUSTA_OK);
  // a step whose play time lies before every sample would play the oldest from a
  // jitter buffer: a glove's newest is solved instead
  const HandSnapshot& first = hand.step(0, 1);
  EXPECT_DOUBLE_EQ(first.haptic.angles[kIndexFlexion1], 0.5);
  const DeviceFeed& feed = hand.port.read_feed();
  EXPECT_EQ(feed.step, 1u);
  EXPECT_EQ(feed.input_sequence, 5u) << "the feed names the sample the step solved";
  EXPECT_NE(feed.input_set_ns, 0) << "and carries its stamp (the link's stage figures need it)";
  // the next sample, the next step: it answers that one
  ASSERT_EQ(hand.port.set_input(OneHand::curled(0.6), HandPort::Driver::kDevice, 1), FRUSTA_OK);
  EXPECT_DOUBLE_EQ(hand.step(0, 2).haptic.angles[kIndexFlexion1], 0.6);
  EXPECT_EQ(hand.port.read_feed().input_sequence, 6u);
  // no new sample: the same one again
  EXPECT_DOUBLE_EQ(hand.step(0, 3).haptic.angles[kIndexFlexion1], 0.6);
  EXPECT_EQ(hand.port.read_feed().input_sequence, 6u);
  hand.port.release_device();
}

TEST(handPipeline, AHostsUntimedSamplesOnTheOwnThreadArePlayedFromTheJitterBuffer) {
  OneHand hand;
  for (int i = 1; i <= 5; ++i)
    ASSERT_EQ(hand.port.set_input(OneHand::curled(0.1 * i), HandPort::Driver::kHost, 1), FRUSTA_OK);
  // played before the oldest sample's time: the oldest, not the newest
  EXPECT_DOUBLE_EQ(hand.step(0, 1).haptic.angles[kIndexFlexion1], 0.1);
  EXPECT_EQ(hand.port.read_feed().input_sequence, 5u) << "the newest the step had";
}

// The step that solves a sample is the step whose device output answers it: the index
// curled into a box brakes in that very step, and the brake is off in the step that
// solves the index open again (no step of lag inside the world). Host-stepped: the
// solver path a glove's newest sample takes on the own thread.
TEST(handPipeline, TheStepThatSolvesASampleCarriesItsForce) {
  const HandModel model = make_hand_model(default_hand_def());
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(model, &hand), FRUSTA_OK);
  ObjectDef box;
  box.pose.position =
      scenes::index_press_box_centre(model, 0.5 * scenes::test_box_spec("press_box").size.x, 0.002);
  ObjectHandle handle;
  ASSERT_EQ(world.add_object(scenes::test_box("press_box"), box, &handle), FRUSTA_OK);
  const GloveCalibration calibration = default_glove_calibration();
  HandState open = scenes::open_hand(), curled = open;
  for (int j = 0; j < 3; ++j) curled.angles[kIndexFlexion1 + j] = calibration.flexion_closed[1][j] * 2500 / 4095;
  const auto brake_after_step = [&](const HandState& input) {
    EXPECT_EQ(world.set_haptic(hand, input), FRUSTA_OK);
    EXPECT_EQ(world.step(), FRUSTA_OK);
    const WorldSnapshot& snap = world.read();
    return snap.hands[0].hand->device.finger_resistance[1];
  };
  for (int i = 0; i < 5; ++i) EXPECT_EQ(brake_after_step(open), 0.0);
  for (int press = 0; press < 3; ++press) {
    EXPECT_GT(brake_after_step(curled), 0.0) << "press " << press;
    for (int i = 0; i < 3; ++i) EXPECT_GT(brake_after_step(curled), 0.0);
    EXPECT_EQ(brake_after_step(open), 0.0) << "release " << press;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(brake_after_step(open), 0.0);
  }
}

}  // namespace
}  // namespace frusta
