// SPDX-License-Identifier: MIT
// The seam between a hand and what drives it: one rule for its inputs, one driver at a
// time, the feed handed over whole, and a hand gone from its port refused to every
// driver that still names it.
#include "port/hand_port.h"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {
namespace {

HandState valid_state() {
  HandState s;
  s.palm_position = vec3(0.1, -0.2, 0.3);
  s.angles[5] = 0.4;
  return s;
}

constexpr uint32_t kHand = 7;  // the generation of the hand the ports are opened to

TEST(HandPort, AnInputThatPassesTheRuleIsTakenWithAUnitRotation) {
  HandPort port(0, 1000.0);
  port.open(kHand);
  EXPECT_FALSE(port.input_fresh());
  HandState s = valid_state();
  s.palm_rotation = 2.0 * glm::angleAxis(0.3, vec3(0.0, 0.0, 1.0));
  ASSERT_EQ(port.set_input(s, HandPort::Driver::kHost, kHand), FRUSTA_OK);
  ASSERT_TRUE(port.input_fresh());
  const TimedInput& taken = port.take_input();
  EXPECT_EQ(taken.state.angles[5], 0.4);
  EXPECT_EQ(taken.state.palm_position, s.palm_position);
  EXPECT_NEAR(glm::length(taken.state.palm_rotation), 1.0, 1e-15);
  EXPECT_GT(taken.set_ns, 0);
  EXPECT_FALSE(port.input_fresh());
}

TEST(HandPort, AnInputThatBreaksTheRuleIsRefusedAndNotTaken) {
  HandPort port(3, 1000.0);
  port.open(kHand);
  HandState s = valid_state();
  s.angles[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(port.set_input(s, HandPort::Driver::kHost, kHand), FRUSTA_ERROR_NOT_FINITE);
  s = valid_state();
  s.angles[7] = 1.01 * kMaxJointAngle;
  EXPECT_EQ(port.set_input(s, HandPort::Driver::kDevice, kHand), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(last_error_message()).find("haptic.angles[7]"), std::string::npos);
  EXPECT_FALSE(port.input_fresh()) << "nothing refused reaches the step";
}

TEST(HandPort, OneDeviceAtATimeAndTheHostWaitsForItsRelease) {
  HandPort port(2, 1000.0);
  port.open(kHand);
  ASSERT_EQ(port.claim_for_device(), FRUSTA_OK);
  EXPECT_TRUE(port.device_driven());
  EXPECT_EQ(port.claim_for_device(), FRUSTA_ERROR_WRONG_STATE);
  EXPECT_NE(std::string(last_error_message()).find("hand 2 already has a glove"), std::string::npos);
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_ERROR_WRONG_STATE);
  EXPECT_NE(std::string(last_error_message()).find("hand 2 is driven by a glove"), std::string::npos);
  EXPECT_FALSE(port.input_fresh());
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kDevice, kHand), FRUSTA_OK);
  port.release_device();
  EXPECT_FALSE(port.device_driven());
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_OK);
  EXPECT_EQ(port.claim_for_device(), FRUSTA_OK);
}

// A glove's sample wakes the world's thread (its tick answers the sample as it lands);
// the host's, played a delay behind, do not.
TEST(HandPort, AGlovesLiveSampleSignalsTheWorldsThreadAndTheHostsDoNot) {
#ifdef _WIN32
  GTEST_SKIP() << "no Wakeup on Windows: its threads keep their own schedules";
#endif
  Wakeup sample_arrived;
  ASSERT_TRUE(sample_arrived.open());
  HandPort port(1, 1000.0, &sample_arrived);
  port.open(kHand);
  const auto now = std::chrono::steady_clock::now;
  ASSERT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_OK);
  ASSERT_EQ(port.set_input_at(valid_state(), 5, HandPort::Driver::kHost, kHand), FRUSTA_OK);
  EXPECT_FALSE(sample_arrived.wait_until(now()));
  ASSERT_EQ(port.claim_for_device(), FRUSTA_OK);
  HandState refused = valid_state();
  refused.angles[2] = std::numeric_limits<double>::infinity();
  ASSERT_NE(port.set_input(refused, HandPort::Driver::kDevice, kHand), FRUSTA_OK);
  EXPECT_FALSE(sample_arrived.wait_until(now())) << "a refused sample is nothing to answer";
  ASSERT_EQ(port.set_input(valid_state(), HandPort::Driver::kDevice, kHand), FRUSTA_OK);
  EXPECT_TRUE(port.take_input().live);
  EXPECT_TRUE(sample_arrived.wait_until(now()));
  EXPECT_FALSE(sample_arrived.wait_until(now())) << "drained by the wait that saw it";
}

TEST(HandPort, AHandGoneFromItsPortIsRefusedToEveryDriverThatStillNamesIt) {
  HandPort port(4, 1000.0);
  EXPECT_EQ(port.generation(), 0u) << "closed until a hand takes it";
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, 0), FRUSTA_ERROR_STALE_ID);
  port.open(kHand);
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand + 1), FRUSTA_ERROR_STALE_ID)
      << "another hand's generation";
  ASSERT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_OK);
  port.close();
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_ERROR_STALE_ID);
  EXPECT_NE(std::string(last_error_message()).find("hand {slot=4"), std::string::npos);
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kDevice, kHand), FRUSTA_ERROR_STALE_ID);
  EXPECT_TRUE(port.idle()) << "every driver has left";

  // the next hand in the slot starts afresh: nothing of the last one's waits for it
  DeviceFeed feed;
  feed.step = 9;
  port.publish_feed(feed);
  port.open(kHand + 1);
  EXPECT_EQ(port.generation(), kHand + 1);
  EXPECT_FALSE(port.input_fresh());
  EXPECT_EQ(port.read_feed().step, 0u);
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand), FRUSTA_ERROR_STALE_ID);
  EXPECT_FALSE(port.input_fresh());
  EXPECT_EQ(port.set_input(valid_state(), HandPort::Driver::kHost, kHand + 1), FRUSTA_OK);
  EXPECT_TRUE(port.input_fresh());
}

TEST(HandPort, TheFeedReachesTheDeviceWhole) {
  HandPort port(0, 500.0);
  EXPECT_EQ(port.rate_hz(), 500.0);
  EXPECT_EQ(port.read_feed().step, 0u) << "nothing published yet";
  DeviceFeed feed;
  feed.step = 7;
  feed.solved = true;
  feed.device.finger_resistance[1] = 2.5;
  port.publish_feed(feed);
  const DeviceFeed& read = port.read_feed();
  EXPECT_EQ(read.step, 7u);
  EXPECT_TRUE(read.solved);
  EXPECT_EQ(read.device.finger_resistance[1], 2.5);
}

}  // namespace
}  // namespace frusta
