// SPDX-License-Identifier: MIT
#include "hand/anthropometry.h"

#include <gtest/gtest.h>

#include "hand/hand_model.h"

namespace frusta {
namespace {

HandDef sized(double length, double breadth) {
  HandDef def = default_hand_def();
  fill_hand_geometry(def, length, breadth);
  return def;
}

TEST(Anthropometry, MiddleFingertipEndsAtHandLength) {
  const HandDef def = sized(0.19, 0.085);
  const int m = FRUSTA_FINGER_MIDDLE;
  // straight middle finger along +x: base + segments + tip hemisphere radius
  const double tip = def.base_position[m][0] + def.segment_length[m][0] +
                     def.segment_length[m][1] + def.segment_length[m][2] +
                     def.joint_radius[m][3];
  EXPECT_NEAR(tip, 0.19, 1e-12);
}

TEST(Anthropometry, IndexLinksFollowBuchholzRatios) {
  const HandDef def = sized(0.20, 0.09);
  const int i = FRUSTA_FINGER_INDEX;
  EXPECT_NEAR(def.segment_length[i][0], 0.265 * 0.20, 1e-12);
  EXPECT_NEAR(def.segment_length[i][1], 0.143 * 0.20, 1e-12);
  // the tip hemisphere takes its radius off the distal phalanx's frustum
  EXPECT_NEAR(def.segment_length[i][2] + def.joint_radius[i][3], 0.097 * 0.20, 1e-12);
  // the thumb's first segment is its metacarpal
  EXPECT_NEAR(def.segment_length[FRUSTA_FINGER_THUMB][0], 0.251 * 0.20, 1e-12);
}

TEST(Anthropometry, RadiiDecreaseProximalToDistalAndScaleWithBreadth) {
  const HandDef a = sized(0.19, 0.08), b = sized(0.19, 0.10);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int j = 0; j + 1 < 4; ++j) EXPECT_GT(a.joint_radius[f][j], a.joint_radius[f][j + 1]);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(b.joint_radius[f][j] / a.joint_radius[f][j], 1.25, 1e-12);
  }
}

TEST(Anthropometry, DefaultsPassTheDefCheckAcrossAdultSizes) {
  for (double length : {0.15, 0.19, 0.23})
    for (double breadth : {0.07, 0.085, 0.11}) {
      HandDef def = sized(length, breadth);
      fill_joint_limits(def);
      EXPECT_EQ(check_hand_def(def), FRUSTA_OK) << length << " x " << breadth;
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) EXPECT_GT(def.segment_length[f][s], 0.0);
    }
}

TEST(Anthropometry, JointLimitsAreAnatomical) {
  HandDef def = default_hand_def();
  fill_joint_limits(def);
  const double deg = 3.14159265358979323846 / 180.0;
  const int i = FRUSTA_FINGER_INDEX;
  EXPECT_NEAR(def.joint_max[i][2], 110 * deg, 1e-12);  // PIP flexes furthest
  EXPECT_NEAR(def.joint_min[i][2], 0.0, 1e-12);        // and does not hyperextend
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) EXPECT_LT(def.joint_min[f][j], def.joint_max[f][j]);
}

}  // namespace
}  // namespace frusta
