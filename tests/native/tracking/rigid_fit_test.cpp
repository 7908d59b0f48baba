// SPDX-License-Identifier: MIT
#include "tracking/rigid_fit.h"

#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "scenes/random_hands.h"

namespace frusta {
namespace {

glm::dquat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(glm::dquat{g(rng), g(rng), g(rng), g(rng)});
}

vec3 random_point(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return vec3{u(rng), u(rng), u(rng)};
}

TEST(RigidFit, RecoversAnyRotationAndTranslationFromPointsExactly) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 1000; ++trial) {
    const glm::dquat r = random_rotation(rng);
    const vec3 t = random_point(rng, 100.0);
    RigidFit fit;
    const int n = 3 + trial % 9;
    for (int i = 0; i < n; ++i) {
      const vec3 m = random_point(rng, 0.1);
      fit.add_point(m, t + r * m, 0.5 + i);
    }
    ASSERT_TRUE(fit.points_fix_rotation());
    glm::dquat rotation;
    vec3 translation;
    fit.solve(&rotation, &translation);
    EXPECT_LT(scenes::rotation_angle(rotation, r), 1e-12);
    EXPECT_LT(glm::length(translation - t), 1e-12);
  }
}

TEST(RigidFit, PointsInALineDoNotFixTheRotationButAxesDo) {
  std::mt19937_64 rng(2);
  const glm::dquat r = random_rotation(rng);
  const vec3 t(1.0, 2.0, 3.0);
  RigidFit fit;
  for (double s : {0.0, 0.03, 0.07}) {
    const vec3 m = s * vec3(1.0, 2.0, -1.0);
    fit.add_point(m, t + r * m, 1.0);
  }
  EXPECT_FALSE(fit.points_fix_rotation());
  const glm::dmat3 model = glm::mat3_cast(random_rotation(rng));
  fit.add_axes(model, glm::mat3_cast(r) * model, 1.0);
  glm::dquat rotation;
  vec3 translation;
  fit.solve(&rotation, &translation);
  EXPECT_LT(scenes::rotation_angle(rotation, r), 1e-12);
  EXPECT_LT(glm::length(translation - t), 1e-12);
}

TEST(RigidFit, WeightsDecideBetweenDisagreeingPoints) {
  RigidFit fit;
  const vec3 square[4] = {{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {0, 0.1, 0}};
  for (const vec3& p : square) fit.add_point(p, p, 1.0);
  fit.add_point(vec3(0.05, 0.05, 0), vec3(0.05, 0.05, 0.01), 1e-9);  // a nearly weightless outlier
  glm::dquat rotation;
  vec3 translation;
  fit.solve(&rotation, &translation);
  EXPECT_LT(glm::length(translation), 1e-10);
  EXPECT_LT(scenes::rotation_angle(rotation, glm::dquat(1, 0, 0, 0)), 1e-9);
}

TEST(SymmetricEigen4, DiagonalisesARotatedDiagonalMatrix) {
  std::mt19937_64 rng(3);
  // Q diag(4, 1, -2, -3) Q^T with Q an orthogonal 4x4 from two quaternion products
  const glm::dquat a = random_rotation(rng), b = random_rotation(rng);
  double q[4][4];
  for (int c = 0; c < 4; ++c) {
    glm::dquat e(c == 0, c == 1, c == 2, c == 3);  // (w, x, y, z) basis
    const glm::dquat image = a * e * b;
    const double column[4] = {image.w, image.x, image.y, image.z};
    for (int r = 0; r < 4; ++r) q[r][c] = column[r];
  }
  const double d[4] = {4.0, 1.0, -2.0, -3.0};
  double m[4][4];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      m[r][c] = 0.0;
      for (int k = 0; k < 4; ++k) m[r][c] += q[r][k] * d[k] * q[c][k];
    }
  double values[4], top[4];
  // quadratic convergence: a handful of sweeps (it once ran all 50, rounding never
  // reaching its stopping test: the palm's fit took 20 us instead of 4)
  EXPECT_LE(symmetric_eigen4(m, values, top), 8);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(values[k], d[k], 1e-13);
  double dot = 0.0;
  for (int r = 0; r < 4; ++r) dot += top[r] * q[r][0];
  EXPECT_NEAR(std::fabs(dot), 1.0, 1e-13);
}

}  // namespace
}  // namespace frusta
