// SPDX-License-Identifier: MIT
#include "hand/anthropometry.h"
#include "hand/kinematics.h"

#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "scenes/random_hands.h"

namespace frusta {
namespace {

HandModel model_of(int side) {
  HandDef def = default_hand_def();
  def.side = side;
  return make_hand_model(def);
}

vec3 point_at(const HandModel& model, const HandState& state, int f, int s, const vec3& local) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  return segment_point(pose, f, s, local);
}

TEST(Kinematics, StraightFingerLiesAlongItsRestAxis) {
  const HandModel m = model_of(FRUSTA_HAND_RIGHT);
  HandState state;
  HandPose pose;
  forward_kinematics(m, state, pose);
  const FingerModel& middle = m.fingers[FRUSTA_FINGER_MIDDLE];
  const FingerPose& p = pose.fingers[FRUSTA_FINGER_MIDDLE];
  // the default middle finger has no fan: its joints line up along +x
  double x = middle.base_position.x;
  for (int s = 0; s < 3; ++s) {
    x += middle.length[s];
    EXPECT_NEAR(p.joint[s + 1].x, x, 1e-12);
    EXPECT_NEAR(p.joint[s + 1].y, middle.base_position.y, 1e-12);
    EXPECT_NEAR(p.joint[s + 1].z, 0.0, 1e-12);
  }
}

TEST(Kinematics, FlexionCurlsTowardsThePalmOnBothHands) {
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const HandModel m = model_of(side);
    HandState straight, bent;
    bent.angles[FRUSTA_FINGER_INDEX * 4 + 1] = 1.0;  // MCP flexion
    HandPose a, b;
    forward_kinematics(m, straight, a);
    forward_kinematics(m, bent, b);
    const vec3 tip_a = a.fingers[FRUSTA_FINGER_INDEX].joint[3];
    const vec3 tip_b = b.fingers[FRUSTA_FINGER_INDEX].joint[3];
    EXPECT_LT(tip_b.z, tip_a.z - 0.03) << "side " << side;  // -z is the palm side
    // a 1 rad MCP flexion turns the whole finger by 1 rad about the MCP
    const vec3 mcp = a.fingers[FRUSTA_FINGER_INDEX].joint[0];
    const double cosine = glm::dot(glm::normalize(tip_a - mcp), glm::normalize(tip_b - mcp));
    EXPECT_NEAR(cosine, std::cos(1.0), 1e-12);
  }
}

TEST(Kinematics, LeftHandMirrorsTheRightThroughTheXZPlane) {
  const HandModel right = model_of(FRUSTA_HAND_RIGHT), left = model_of(FRUSTA_HAND_LEFT);
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    HandState state = scenes::random_hand_state(right, rng);
    state.palm_position = vec3(0.0);
    state.palm_rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
    HandPose r, l;
    forward_kinematics(right, state, r);
    forward_kinematics(left, state, l);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(l.fingers[f].joint[j].x, r.fingers[f].joint[j].x, 1e-14);
        EXPECT_NEAR(l.fingers[f].joint[j].y, -r.fingers[f].joint[j].y, 1e-14);
        EXPECT_NEAR(l.fingers[f].joint[j].z, r.fingers[f].joint[j].z, 1e-14);
      }
  }
}

TEST(Kinematics, SegmentsKeepTheirLengthAndFramesStayRightHanded) {
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const HandModel m = model_of(side);
    std::mt19937_64 rng(11 + side);
    for (int trial = 0; trial < 1000; ++trial) {
      const HandState state = scenes::random_hand_state(m, rng);
      HandPose pose;
      forward_kinematics(m, state, pose);
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        for (int s = 0; s < 3; ++s) {
          const FingerPose& p = pose.fingers[f];
          EXPECT_NEAR(glm::length(p.joint[s + 1] - p.joint[s]), m.fingers[f].length[s], 1e-14);
          const glm::dmat3& r = p.segment_rotation[s];
          EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
          // x runs along the segment, y is the flexion axis
          EXPECT_NEAR(glm::dot(r[0], glm::normalize(p.joint[s + 1] - p.joint[s])), 1.0, 1e-12);
          EXPECT_NEAR(std::fabs(glm::dot(r[1], p.flexion_axis)), 1.0, 1e-12);
        }
    }
  }
}

TEST(Kinematics, ClampKeepsAnglesInsideTheLimits) {
  const HandModel m = model_of(FRUSTA_HAND_RIGHT);
  HandState s;
  s.angles.fill(10.0);
  clamp_to_limits(m, s);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(s.angles[f * 4 + j], m.fingers[f].joint_max[j]);
  s.angles.fill(-10.0);
  clamp_to_limits(m, s);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(s.angles[f * 4 + j], m.fingers[f].joint_min[j]);
}

// Property: every column of the analytic Jacobian equals the central finite
// difference of forward kinematics, for random states, points and both hands.
TEST(Kinematics, PointJacobianMatchesCentralDifferences) {
  constexpr double h = 1e-6;
  // central differences err by ~h^2 |P'''| / 6 plus rounding ~1e-16 / h
  constexpr double kTolerance = 1e-8;
  int checked = 0;
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const HandModel m = model_of(side);
    std::mt19937_64 rng(1234 + side);
    std::uniform_real_distribution<double> offset(-0.02, 0.06);
    for (int trial = 0; trial < 5000; ++trial) {
      const HandState state = scenes::random_hand_state(m, rng);
      const int f = static_cast<int>(rng() % FRUSTA_FINGER_COUNT);
      const int s = static_cast<int>(rng() % 3);
      const vec3 local(offset(rng), offset(rng), offset(rng));

      HandPose pose;
      forward_kinematics(m, state, pose);
      const vec3 p = segment_point(pose, f, s, local);
      double jacobian[3 * kJacobianColumns];
      point_jacobian(pose, f, s, p, jacobian);

      for (int col = 0; col < kJacobianColumns; ++col) {
        HandState plus = state, minus = state;
        if (col < 4) {
          plus.angles[f * 4 + col] += h;
          minus.angles[f * 4 + col] -= h;
        } else if (col < 7) {
          plus.palm_position[col - 4] += h;
          minus.palm_position[col - 4] -= h;
        } else {
          vec3 axis(0.0);
          axis[col - 7] = 1.0;  // world-frame rotation vector: left-multiply
          plus.palm_rotation = glm::angleAxis(h, axis) * state.palm_rotation;
          minus.palm_rotation = glm::angleAxis(-h, axis) * state.palm_rotation;
        }
        const vec3 fd = (point_at(m, plus, f, s, local) - point_at(m, minus, f, s, local)) / (2 * h);
        for (int row = 0; row < 3; ++row)
          ASSERT_NEAR(jacobian[row * kJacobianColumns + col], fd[row], kTolerance)
              << "side " << side << " finger " << f << " segment " << s << " column " << col;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 2 * 5000 * kJacobianColumns);
}

}  // namespace
}  // namespace frusta
