// SPDX-License-Identifier: MIT
// Hands through the C ABI (native/src/capi/api_hand.cpp) against the internal model
// and kinematics, and against geometry worked out independently here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <random>
#include <vector>

#include "capi/convert.h"
#include "capi_fixture.h"
#include "frusta/frusta.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"

namespace frusta {
namespace {

using testing::interior_angles;
using testing::random_pose;
using testing::ScopedHand;
// suite names start with "capi" so that `ctest -R capi` selects them
using capiHand = testing::CapiTest;

constexpr int kJacobianSize = FRUSTA_POINT_JACOBIAN_LENGTH;
using Segments = std::array<frusta_segment, FRUSTA_HAND_SEGMENT_COUNT>;
using testing::Angles;

frusta_hand_def def_of(int side) {
  frusta_hand_def def = frusta_default_hand_def();
  def.side = side;
  return def;
}

Segments segments_of(frusta_hand_id hand) {
  Segments s{};
  int32_t count = 0;
  EXPECT_EQ(frusta_hand_get_segments(hand, s.data(), FRUSTA_HAND_SEGMENT_COUNT, &count), FRUSTA_OK);
  EXPECT_EQ(count, FRUSTA_HAND_SEGMENT_COUNT);
  return s;
}

// The whole Jacobian (its count checked) and the point.
frusta_result point_jacobian_of(frusta_hand_id hand, int finger, int segment, const double local[3],
                                double* point, double* jacobian) {
  int32_t count = 0;
  const frusta_result r = frusta_hand_point_jacobian(hand, finger, segment, local, point, jacobian,
                                                     kJacobianSize, &count);
  if (r == FRUSTA_OK) {
    EXPECT_EQ(count, kJacobianSize);
  }
  return r;
}

Angles angles_of(frusta_hand_id hand) {
  Angles a{};
  int32_t count = 0;
  EXPECT_EQ(frusta_hand_get_joint_angles(hand, a.data(), FRUSTA_HAND_JOINT_COUNT, &count),
            FRUSTA_OK);
  EXPECT_EQ(count, FRUSTA_HAND_JOINT_COUNT);
  return a;
}

std::vector<frusta_sphere> palm_of(frusta_hand_id hand) {
  int32_t count = 0;
  EXPECT_EQ(frusta_hand_get_palm_spheres(hand, nullptr, 0, &count), FRUSTA_OK);
  std::vector<frusta_sphere> spheres(static_cast<size_t>(count));
  EXPECT_EQ(frusta_hand_get_palm_spheres(hand, spheres.data(), count, &count), FRUSTA_OK);
  return spheres;
}

vec3 v(const double p[3]) { return vec3(p[0], p[1], p[2]); }

// Rotation matrix of a unit quaternion (x, y, z, w), written out here rather than
// taken from glm, as the independent reference for the palm pose.
std::array<std::array<double, 3>, 3> rotation_of(const double q[4]) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
           {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
           {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

// q' = exp(angle/2 * axis) * q: q turned by `angle` about the world axis e_k
void turn_world(double q[4], int k, double angle) {
  double d[4] = {0, 0, 0, std::cos(0.5 * angle)};
  d[k] = std::sin(0.5 * angle);
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  q[0] = d[3] * x + d[0] * w + d[1] * z - d[2] * y;
  q[1] = d[3] * y - d[0] * z + d[1] * w + d[2] * x;
  q[2] = d[3] * z + d[0] * y - d[1] * x + d[2] * w;
  q[3] = d[3] * w - d[0] * x - d[1] * y - d[2] * z;
}

// The internal model posed as the ABI is asked to pose it.
struct Reference {
  HandModel model;
  HandState state;
  HandPose pose;
};

Reference internal_hand(const frusta_hand_def& def, const frusta_pose& palm, const Angles& angles) {
  Reference r;
  r.model = make_hand_model(read_hand_def(def));
  r.state.palm_position = v(palm.position);
  const glm::dquat q(palm.rotation[3], palm.rotation[0], palm.rotation[1], palm.rotation[2]);
  r.state.palm_rotation = q / glm::length(q);
  std::copy(angles.begin(), angles.end(), r.state.angles.begin());
  clamp_to_limits(r.model, r.state);
  forward_kinematics(r.model, r.state, r.pose);
  return r;
}

void expect_vec_near(const double got[3], const vec3& want, double tolerance, const char* what) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tolerance) << what << "[" << k << "]";
}

TEST_F(capiHand, SegmentsEqualInternalForwardKinematics) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> wide(-3.0, 3.0);  // mostly beyond the limits
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const frusta_hand_def def = def_of(side);
    ScopedHand hand(def);
    for (int trial = 0; trial < 50; ++trial) {
      const frusta_pose palm = random_pose(rng);
      Angles angles = interior_angles(def, rng);
      if (trial % 2) std::generate(angles.begin(), angles.end(), [&] { return wide(rng); });
      ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &palm), FRUSTA_OK);
      ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
                FRUSTA_OK);
      const Reference ref = internal_hand(def, palm, angles);
      const Segments got = segments_of(hand.get());
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
          SCOPED_TRACE(::testing::Message() << "side " << side << " trial " << trial << " finger "
                                            << f << " segment " << s);
          const Segment want = finger_segment(ref.model, ref.pose, f, s);
          const frusta_segment& g = got[static_cast<size_t>(f * 3 + s)];
          expect_vec_near(g.proximal, want.proximal, 1e-14, "proximal");
          expect_vec_near(g.distal, want.distal, 1e-14, "distal");
          EXPECT_EQ(g.proximal_radius, want.proximal_radius);
          EXPECT_EQ(g.distal_radius, want.distal_radius);
        }
      const std::vector<frusta_sphere> palm_spheres = palm_of(hand.get());
      ASSERT_EQ(palm_spheres.size(), ref.model.palm_spheres.size());
      for (size_t i = 0; i < palm_spheres.size(); ++i) {
        const Sphere want = palm_sphere(ref.model, ref.pose, static_cast<int>(i));
        expect_vec_near(palm_spheres[i].center, want.center, 1e-14, "palm centre");
        EXPECT_EQ(palm_spheres[i].radius, want.radius);
      }
      // the Jacobian and point of a material point
      const double local[3] = {0.01, 0.002, -0.004};
      const int f = trial % FRUSTA_FINGER_COUNT, s = trial % FRUSTA_SEGMENTS_PER_FINGER;
      double point[3], jacobian[kJacobianSize];
      ASSERT_EQ(point_jacobian_of(hand.get(), f, s, local, point, jacobian), FRUSTA_OK);
      const vec3 want_point = segment_point(ref.pose, f, s, v(local));
      expect_vec_near(point, want_point, 1e-14, "jacobian point");
      double want_jacobian[kJacobianSize];
      point_jacobian(ref.pose, f, s, want_point, want_jacobian);
      for (int i = 0; i < kJacobianSize; ++i) EXPECT_NEAR(jacobian[i], want_jacobian[i], 1e-14);
    }
  }
}

TEST_F(capiHand, AnglesInsideTheLimitsReadBackExactly) {
  std::mt19937_64 rng(12);
  const frusta_hand_def def = frusta_default_hand_def();
  ScopedHand hand(def);
  for (int trial = 0; trial < 20; ++trial) {
    const Angles angles = interior_angles(def, rng);
    ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_OK);
    EXPECT_EQ(angles_of(hand.get()), angles);
  }
}

TEST_F(capiHand, SetJointAnglesClampsBeyondLimitFiniteValuesToTheDefsLimits) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> any(-FRUSTA_MAX_JOINT_ANGLE, FRUSTA_MAX_JOINT_ANGLE);
  frusta_hand_def def = frusta_default_hand_def();
  def.joint_min[FRUSTA_FINGER_INDEX][1] = 0.2;  // a custom, narrow range
  def.joint_max[FRUSTA_FINGER_INDEX][1] = 0.3;
  ScopedHand hand(def);
  for (int trial = 0; trial < 50; ++trial) {
    Angles angles{};
    std::generate(angles.begin(), angles.end(), [&] { return any(rng); });
    if (trial == 0) angles.fill(FRUSTA_MAX_JOINT_ANGLE);  // the largest accepted magnitude
    if (trial == 1) angles.fill(-FRUSTA_MAX_JOINT_ANGLE);
    ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_OK);
    const Angles got = angles_of(hand.get());
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
        const size_t i = static_cast<size_t>(f * 4 + j);
        EXPECT_EQ(got[i], std::clamp(angles[i], def.joint_min[f][j], def.joint_max[f][j]))
            << "finger " << f << " joint " << j << " set to " << angles[i];
      }
  }
  // the geometry follows the clamped angles, not the requested ones
  Angles beyond{};
  beyond[FRUSTA_FINGER_INDEX * 4 + 1] = 1.5;
  ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), beyond.data(), FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  const Segments clamped = segments_of(hand.get());
  Angles at_limit{};
  at_limit[FRUSTA_FINGER_INDEX * 4 + 1] = 0.3;
  ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), at_limit.data(), FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  const Segments limit = segments_of(hand.get());
  EXPECT_EQ(std::memcmp(clamped.data(), limit.data(), sizeof clamped), 0);
}

TEST_F(capiHand, NewHandStartsAtZeroClampedIntoTheLimits) {
  frusta_hand_def def = frusta_default_hand_def();
  def.joint_min[FRUSTA_FINGER_RING][2] = 0.4;  // zero lies below this range
  def.joint_max[FRUSTA_FINGER_RING][2] = 0.6;
  def.joint_min[FRUSTA_FINGER_THUMB][0] = -0.5;  // and above this one
  def.joint_max[FRUSTA_FINGER_THUMB][0] = -0.25;
  ScopedHand hand(def);
  Angles want{};
  want[FRUSTA_FINGER_RING * 4 + 2] = 0.4;
  want[FRUSTA_FINGER_THUMB * 4 + 0] = -0.25;
  EXPECT_EQ(angles_of(hand.get()), want);
  // and its geometry is that of the clamped angles
  const frusta_pose identity{{0, 0, 0}, {0, 0, 0, 1}};
  const Reference ref = internal_hand(def, identity, want);
  const Segments got = segments_of(hand.get());
  const Segment ring_tip = finger_segment(ref.model, ref.pose, FRUSTA_FINGER_RING, 2);
  expect_vec_near(got[FRUSTA_FINGER_RING * 3 + 2].distal, ring_tip.distal, 1e-15, "ring tip");
}

TEST_F(capiHand, PalmPoseMovesTheHandRigidly) {
  std::mt19937_64 rng(14);
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const frusta_hand_def def = def_of(side);
    ScopedHand hand(def);
    for (int trial = 0; trial < 20; ++trial) {
      const Angles angles = interior_angles(def, rng);
      ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
                FRUSTA_OK);
      const frusta_pose identity{{0, 0, 0}, {0, 0, 0, 1}};
      ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &identity), FRUSTA_OK);
      const Segments rest = segments_of(hand.get());
      const std::vector<frusta_sphere> rest_palm = palm_of(hand.get());
      const frusta_pose palm = random_pose(rng);
      ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &palm), FRUSTA_OK);
      const Segments moved = segments_of(hand.get());
      const std::vector<frusta_sphere> moved_palm = palm_of(hand.get());
      const auto r = rotation_of(palm.rotation);
      auto place = [&](const double p[3], double out[3]) {
        for (int i = 0; i < 3; ++i)
          out[i] = palm.position[i] + r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2];
      };
      for (size_t i = 0; i < rest.size(); ++i) {
        double want[3];
        place(rest[i].proximal, want);
        expect_vec_near(moved[i].proximal, v(want), 1e-12, "proximal");
        place(rest[i].distal, want);
        expect_vec_near(moved[i].distal, v(want), 1e-12, "distal");
        EXPECT_EQ(moved[i].proximal_radius, rest[i].proximal_radius);
      }
      ASSERT_EQ(moved_palm.size(), rest_palm.size());
      for (size_t i = 0; i < rest_palm.size(); ++i) {
        double want[3];
        place(rest_palm[i].center, want);
        expect_vec_near(moved_palm[i].center, v(want), 1e-12, "palm centre");
      }
    }
  }
}

TEST_F(capiHand, PalmQuaternionIsNormalised) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  const frusta_hand_def def = frusta_default_hand_def();
  ScopedHand hand(def);
  const Angles angles = interior_angles(def, rng);
  ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  for (int trial = 0; trial < 50; ++trial) {
    const frusta_pose unit = random_pose(rng);
    ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &unit), FRUSTA_OK);
    const Segments want = segments_of(hand.get());
    // any norm in [0.5, 2], including both ends, and the opposite quaternion
    frusta_pose scaled = unit;
    const double s = trial == 0       ? 0.5
                     : trial == 1     ? 2.0
                     : trial % 3 == 0 ? -scale(rng)
                                      : scale(rng);
    for (double& q : scaled.rotation) q *= s;
    ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &scaled), FRUSTA_OK) << "scale " << s;
    const Segments got = segments_of(hand.get());
    for (size_t i = 0; i < got.size(); ++i) {
      expect_vec_near(got[i].proximal, v(want[i].proximal), 1e-14, "proximal");
      expect_vec_near(got[i].distal, v(want[i].distal), 1e-14, "distal");
    }
  }
  // just outside [0.5, 2] is refused and changes nothing
  const frusta_pose before = random_pose(rng);
  ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &before), FRUSTA_OK);
  const Segments kept = segments_of(hand.get());
  for (double s : {0.4999, 2.0001, 1e-200}) {
    frusta_pose bad = before;
    for (double& q : bad.rotation) q *= s;
    ExpectError(frusta_hand_set_palm_pose(hand.get(), &bad), FRUSTA_ERROR_OUT_OF_RANGE,
                "pose.rotation");
    const Segments after = segments_of(hand.get());
    EXPECT_EQ(std::memcmp(after.data(), kept.data(), sizeof kept), 0) << "scale " << s;
  }
}

TEST_F(capiHand, LeftHandIsTheRightMirroredThroughThePalmXZPlane) {
  std::mt19937_64 rng(16);
  const frusta_hand_def right_def = def_of(FRUSTA_HAND_RIGHT);
  ScopedHand right(right_def), left(def_of(FRUSTA_HAND_LEFT));
  for (int trial = 0; trial < 50; ++trial) {
    const Angles angles = interior_angles(right_def, rng);
    for (frusta_hand_id h : {right.get(), left.get()})
      ASSERT_EQ(frusta_hand_set_joint_angles(h, angles.data(), FRUSTA_HAND_JOINT_COUNT), FRUSTA_OK);
    const Segments r = segments_of(right.get()), l = segments_of(left.get());
    for (size_t i = 0; i < r.size(); ++i) {
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " segment " << i);
      const vec3 mirror(1.0, -1.0, 1.0);
      expect_vec_near(l[i].proximal, v(r[i].proximal) * mirror, 1e-15, "proximal");
      expect_vec_near(l[i].distal, v(r[i].distal) * mirror, 1e-15, "distal");
      EXPECT_EQ(l[i].proximal_radius, r[i].proximal_radius);
      EXPECT_EQ(l[i].distal_radius, r[i].distal_radius);
    }
    // a point on a segment's back (local +z) is mirrored too, and so are the finger
    // joints' Jacobian columns: mirrored motion for the same angle change
    const int f = trial % FRUSTA_FINGER_COUNT, s = trial % FRUSTA_SEGMENTS_PER_FINGER;
    const double local[3] = {0.005, 0.0, 0.004};
    double rp[3], lp[3], rj[kJacobianSize], lj[kJacobianSize];
    ASSERT_EQ(point_jacobian_of(right.get(), f, s, local, rp, rj), FRUSTA_OK);
    ASSERT_EQ(point_jacobian_of(left.get(), f, s, local, lp, lj), FRUSTA_OK);
    expect_vec_near(lp, v(rp) * vec3(1.0, -1.0, 1.0), 1e-15, "dorsal point");
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < FRUSTA_JOINTS_PER_FINGER; ++col) {
        const double sign = row == 1 ? -1.0 : 1.0;
        EXPECT_NEAR(lj[row * 10 + col], sign * rj[row * 10 + col], 1e-14)
            << "finger " << f << " segment " << s << " row " << row << " joint " << col;
      }
  }
  const std::vector<frusta_sphere> rp = palm_of(right.get()), lp = palm_of(left.get());
  ASSERT_EQ(rp.size(), lp.size());
  for (size_t i = 0; i < rp.size(); ++i)
    expect_vec_near(lp[i].center, v(rp[i].center) * vec3(1.0, -1.0, 1.0), 1e-15, "palm");
}

TEST_F(capiHand, FlexionCurlsTowardsThePalmOnBothHands) {
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    ScopedHand hand(def_of(side));
    const Segments straight = segments_of(hand.get());
    Angles bent{};
    for (int f = 1; f < FRUSTA_FINGER_COUNT; ++f) bent[static_cast<size_t>(f * 4 + 2)] = 1.0;
    ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), bent.data(), FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_OK);
    const Segments curled = segments_of(hand.get());
    for (int f = 1; f < FRUSTA_FINGER_COUNT; ++f) {
      const size_t tip = static_cast<size_t>(f * 3 + 2);
      EXPECT_LT(curled[tip].distal[2], straight[tip].distal[2] - 0.01)
          << "side " << side << " finger " << f << ": -z is the palm side";
    }
  }
}

// Each Jacobian column is the derivative of the point's world position, taken here by
// central differences through the ABI itself (angles, palm position, palm rotation).
TEST_F(capiHand, PointJacobianMatchesFiniteDifferences) {
  std::mt19937_64 rng(17);
  constexpr double h = 1e-6;
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
    const frusta_hand_def def = def_of(side);
    ScopedHand hand(def);
    for (int trial = 0; trial < 30; ++trial) {
      const int f = trial % FRUSTA_FINGER_COUNT, s = (trial / 5) % FRUSTA_SEGMENTS_PER_FINGER;
      const Angles angles = interior_angles(def, rng);
      const frusta_pose palm = random_pose(rng);
      const double local[3] = {0.01, 0.003, -0.005};
      auto point_at = [&](const Angles& a, const frusta_pose& p) {
        double point[3], jacobian[kJacobianSize];
        EXPECT_EQ(frusta_hand_set_palm_pose(hand.get(), &p), FRUSTA_OK);
        EXPECT_EQ(frusta_hand_set_joint_angles(hand.get(), a.data(), FRUSTA_HAND_JOINT_COUNT),
                  FRUSTA_OK);
        EXPECT_EQ(point_jacobian_of(hand.get(), f, s, local, point, jacobian), FRUSTA_OK);
        return v(point);
      };
      point_at(angles, palm);
      double jacobian[kJacobianSize];
      ASSERT_EQ(point_jacobian_of(hand.get(), f, s, local, nullptr, jacobian), FRUSTA_OK);
      for (int col = 0; col < 10; ++col) {
        Angles ap = angles, am = angles;
        frusta_pose pp = palm, pm = palm;
        if (col < 4) {
          ap[static_cast<size_t>(f * 4 + col)] += h;
          am[static_cast<size_t>(f * 4 + col)] -= h;
        } else if (col < 7) {
          pp.position[col - 4] += h;
          pm.position[col - 4] -= h;
        } else {
          turn_world(pp.rotation, col - 7, h);
          turn_world(pm.rotation, col - 7, -h);
        }
        const vec3 numeric = (point_at(ap, pp) - point_at(am, pm)) / (2.0 * h);
        for (int row = 0; row < 3; ++row)
          EXPECT_NEAR(jacobian[row * 10 + col], numeric[row], 1e-8)
              << "side " << side << " finger " << f << " segment " << s << " column " << col
              << " row " << row;
      }
    }
  }
}

TEST_F(capiHand, MiddleFingertipEndsAtHandLengthForAnySize) {
  for (double length : {0.15, 0.19, 0.23}) {
    for (double breadth : {0.07, 0.085, 0.1}) {
      frusta_hand_def def = frusta_default_hand_def();
      ASSERT_EQ(frusta_hand_def_set_size(&def, length, breadth), FRUSTA_OK) << frusta_last_error();
      ScopedHand hand(def);
      const frusta_segment tip = segments_of(hand.get())[FRUSTA_FINGER_MIDDLE * 3 + 2];
      EXPECT_NEAR(tip.distal[0] + tip.distal_radius, length, 1e-12)
          << "length " << length << " breadth " << breadth;
      EXPECT_NEAR(tip.distal[1], def.base_position[FRUSTA_FINGER_MIDDLE][1], 1e-12);
    }
  }
}

TEST_F(capiHand, HandsAreIndependent) {
  std::mt19937_64 rng(18);
  const frusta_hand_def def = frusta_default_hand_def();
  ScopedHand a(def), b(def);
  const Segments b_before = segments_of(b.get());
  const Angles angles = interior_angles(def, rng);
  const frusta_pose palm = random_pose(rng);
  ASSERT_EQ(frusta_hand_set_joint_angles(a.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  ASSERT_EQ(frusta_hand_set_palm_pose(a.get(), &palm), FRUSTA_OK);
  const Segments b_after = segments_of(b.get());
  EXPECT_EQ(std::memcmp(b_before.data(), b_after.data(), sizeof b_before), 0);
  EXPECT_EQ(angles_of(b.get()), Angles{});
}

TEST_F(capiHand, FailedCallsChangeNothing) {
  std::mt19937_64 rng(19);
  const frusta_hand_def def = frusta_default_hand_def();
  ScopedHand hand(def);
  const Angles angles = interior_angles(def, rng);
  const frusta_pose palm = random_pose(rng);
  ASSERT_EQ(frusta_hand_set_joint_angles(hand.get(), angles.data(), FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  ASSERT_EQ(frusta_hand_set_palm_pose(hand.get(), &palm), FRUSTA_OK);
  const Segments before = segments_of(hand.get());

  Angles bad = interior_angles(def, rng);
  bad[19] = std::nan("");
  ExpectError(frusta_hand_set_joint_angles(hand.get(), bad.data(), FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_ERROR_NOT_FINITE, "angles[19]");
  bad[19] = 0.0;
  bad[0] = -100.5;
  ExpectError(frusta_hand_set_joint_angles(hand.get(), bad.data(), FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_ERROR_OUT_OF_RANGE, "angles[0]");
  frusta_pose moved = random_pose(rng);
  moved.position[2] = 1.0000001e6;
  ExpectError(frusta_hand_set_palm_pose(hand.get(), &moved), FRUSTA_ERROR_OUT_OF_RANGE,
              "pose.position[2]");
  moved = random_pose(rng);
  moved.rotation[1] = std::numeric_limits<double>::infinity();
  ExpectError(frusta_hand_set_palm_pose(hand.get(), &moved), FRUSTA_ERROR_NOT_FINITE,
              "pose.rotation[1]");
  EXPECT_EQ(angles_of(hand.get()), angles);
  const Segments after = segments_of(hand.get());
  EXPECT_EQ(std::memcmp(before.data(), after.data(), sizeof before), 0);
}

}  // namespace
}  // namespace frusta
