// SPDX-License-Identifier: MIT
#include "hand/anthropometry.h"
#include "core/error.h"
#include "hand/hand_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace frusta {
namespace {

TEST(HandModel, CheckNamesTheFaultyField) {
  HandDef def = default_hand_def();
  def.segment_length[3][1] = 0.0;
  EXPECT_EQ(check_hand_def(def), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("segment_length[3][1]"), std::string::npos);

  def = default_hand_def();
  def.joint_radius[0][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_hand_def(def), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("joint_radius[0][2]"), std::string::npos);

  def = default_hand_def();
  def.joint_min[2][1] = def.joint_max[2][1] + 0.1;
  EXPECT_EQ(check_hand_def(def), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("joint_max[2][1]"), std::string::npos);
}

TEST(HandModel, PalmSpheresCoverThePalmRectangle) {
  const HandDef def = default_hand_def();
  const HandModel m = make_hand_model(def);
  ASSERT_GE(m.palm_spheres.size(), 4u);
  // every point of the palm's mid-plane rectangle lies inside some sphere
  const double r = 0.5 * def.palm_thickness;
  for (double x = r; x <= def.palm_length - r; x += 0.002)
    for (double y = -0.5 * def.palm_breadth + r; y <= 0.5 * def.palm_breadth - r; y += 0.002) {
      bool covered = false;
      for (const Sphere& s : m.palm_spheres)
        covered = covered || std::hypot(s.center.x - x, s.center.y - y) <= s.radius;
      EXPECT_TRUE(covered) << x << ", " << y;
    }
}

TEST(HandModel, LeftPalmIsTheMirrorOfTheRight) {
  HandDef def = default_hand_def();
  const HandModel right = make_hand_model(def);
  def.side = FRUSTA_HAND_LEFT;
  const HandModel left = make_hand_model(def);
  ASSERT_EQ(left.palm_spheres.size(), right.palm_spheres.size());
  EXPECT_TRUE(left.left);
  for (size_t i = 0; i < left.palm_spheres.size(); ++i) {
    EXPECT_DOUBLE_EQ(left.palm_spheres[i].center.x, right.palm_spheres[i].center.x);
    EXPECT_DOUBLE_EQ(left.palm_spheres[i].center.y, -right.palm_spheres[i].center.y);
  }
}

}  // namespace
}  // namespace frusta
