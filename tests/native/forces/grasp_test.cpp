// SPDX-License-Identifier: MIT
// The grasp condition (forces/grasp.h): the load the best opposing pair of pushes bears.
#include "forces/grasp.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frusta {
namespace {

constexpr int kThumbTip = 2, kIndexTip = 5, kMiddleTip = 8;

TEST(Grasp, TwoOpposingPadsBearTwiceMuTimesTheWeakerPush) {
  BodyPushes p{};
  p[kThumbTip] = vec3(0, 0, 3.0);
  p[kIndexTip] = vec3(0, 0, -1.0);
  EXPECT_DOUBLE_EQ(squeeze_load(p, 0.8), 2 * 0.8 * 1.0);  // the stronger pad's excess holds nothing
}

TEST(Grasp, PushesThatDoNotOpposeHoldNothing) {
  BodyPushes p{};
  p[kIndexTip] = vec3(0, 0, 5.0);
  p[kMiddleTip] = vec3(0, 0.5, 5.0);  // side by side, pushing the same way
  p[kPalmBody] = vec3(0, 1.0, 0.0);   // at right angles
  EXPECT_EQ(squeeze_load(p, 1.0), 0.0);
  EXPECT_EQ(squeeze_load(BodyPushes{}, 1.0), 0.0);
}

TEST(Grasp, AnObliquePairBearsItsShareAlongTheirAxis) {
  BodyPushes p{};
  p[kThumbTip] = vec3(1.0, 0, 0);
  p[kPalmBody] = 2.0 * vec3(-0.5, std::sqrt(3.0) / 2, 0);  // 120 degrees apart: cos -1/2
  EXPECT_NEAR(squeeze_load(p, 1.0), 2 * 1.0 * 0.5, 1e-12);
  p[kPalmBody] = vec3(-0.2, 1.0, 0.0);  // ~101 degrees: not opposing
  EXPECT_EQ(squeeze_load(p, 1.0), 0.0);
}

TEST(Grasp, TheBestPairCountsNotTheSum) {
  BodyPushes p{};
  for (int f = 1; f < 5; ++f) p[static_cast<size_t>(3 * f + 2)] = vec3(0, 0, -1.0);  // four fingertips
  p[kThumbTip] = vec3(0, 0, 1.0);
  EXPECT_DOUBLE_EQ(squeeze_load(p, 0.5), 2 * 0.5 * 1.0);
}

}  // namespace
}  // namespace frusta
