// SPDX-License-Identifier: MIT
#include "tracking/one_euro.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "scenes/random_hands.h"
#include "tracking/hand_fit.h"

namespace frusta {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kDt = 1.0 / 90.0;  // a tracker's frame, seconds

TEST(OneEuro, AConstantPassesUnchanged) {
  const OneEuroParams p{1.0, 2.0, 1.0};
  OneEuro<double> scalar;
  OneEuro<vec3> vector;
  OneEuroRotation rotation;
  const vec3 v(0.1, -0.25, 0.4);
  const glm::dquat q = glm::angleAxis(0.8, glm::normalize(vec3(1.0, -2.0, 0.5)));
  for (int i = 0; i < 200; ++i) {
    EXPECT_EQ(scalar.filter(0.37, kDt, p), 0.37);
    EXPECT_EQ(vector.filter(v, kDt, p), v);
    EXPECT_LT(scenes::rotation_angle(rotation.filter(q, kDt, p), q), 1e-12);
  }
}

// at rest (beta 0) a step is a first-order low-pass's: (1 - alpha)^n of it is left after
// n samples, about 1/e after 1 / (2 pi min_cutoff) s
TEST(OneEuro, AStepIsFollowedWithTheDocumentedLag) {
  for (double min_cutoff : {0.5, 1.0, 4.0}) {
    const OneEuroParams p{min_cutoff, 0.0, 1.0};
    OneEuro<double> f;
    f.filter(0.0, kDt, p);
    const double a = one_euro_alpha(min_cutoff, kDt);
    const double tau = 1.0 / (2.0 * kPi * min_cutoff);
    double out = 0.0, reached_at = -1.0;
    for (int n = 1; n <= 2000; ++n) {
      out = f.filter(1.0, kDt, p);
      EXPECT_NEAR(1.0 - out, std::pow(1.0 - a, n), 1e-12);
      if (reached_at < 0.0 && out >= 1.0 - std::exp(-1.0)) reached_at = n * kDt;
    }
    // 63 % of the step within a sample of tau (the sampling rounds it)
    EXPECT_NEAR(reached_at, tau, 1.5 * kDt) << min_cutoff << " Hz";
  }
}

// moving, the cutoff rises: beta > 0 follows a step sooner than beta 0
TEST(OneEuro, SpeedRaisesTheCutoff) {
  const auto time_to_63 = [](double beta) {
    const OneEuroParams p{1.0, beta, 1.0};
    OneEuro<vec3> f;
    f.filter(vec3(0.0), kDt, p);
    for (int n = 1; n < 1000; ++n)
      if (f.filter(vec3(0.05, 0.0, 0.0), kDt, p).x >= 0.05 * (1.0 - std::exp(-1.0))) return n * kDt;
    return 1e9;
  };
  const double slow = time_to_63(0.0), fast = time_to_63(20.0);
  std::printf("a 5 cm step, 63 %% after %.0f ms at beta 0, %.0f ms at beta 20/m\n", 1e3 * slow,
              1e3 * fast);
  EXPECT_LT(fast, 0.5 * slow);
}

TEST(OneEuro, ARotationStepIsFollowedLikeAScalarsAlongTheShorterWay) {
  const OneEuroParams p{1.0, 0.0, 1.0};
  OneEuroRotation f;
  const glm::dquat from(1.0, 0.0, 0.0, 0.0);
  const vec3 axis = glm::normalize(vec3(0.3, 1.0, -0.2));
  // the same rotation given with the other sign: the shorter way is still 0.6 rad
  const glm::dquat to = -glm::angleAxis(0.6, axis);
  f.filter(from, kDt, p);
  const double a = one_euro_alpha(1.0, kDt);
  for (int n = 1; n <= 100; ++n) {
    const glm::dquat out = f.filter(to, kDt, p);
    EXPECT_NEAR(scenes::rotation_angle(out, to), 0.6 * std::pow(1.0 - a, n), 1e-9);
  }
}

// noise of sigma s at rest: what is left, measured (the figure the README quotes)
// with the fitter's default parameters for the palm position, at a tracker's 90 Hz
TEST(OneEuro, NoiseAtRestIsReducedByAMeasuredFactor) {
  const HandFitOptions defaults;
  const OneEuroParams p{defaults.filter_min_cutoff, defaults.filter_beta, defaults.filter_d_cutoff};
  for (double sigma : {0.001, 0.002, 0.005}) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, sigma);
    OneEuro<vec3> f;
    const vec3 rest(0.1, 0.2, 0.3);
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < 9090; ++i) {
      const vec3 out = f.filter(rest + vec3(noise(rng), noise(rng), noise(rng)), kDt, p);
      if (i < 90) continue;  // a second to settle
      const vec3 d = out - rest;
      sum += glm::dot(d, d);
      n += 3;
    }
    const double factor = sigma / std::sqrt(sum / n);
    std::printf("noise %.0f mm at rest: reduced %.1f times\n", 1e3 * sigma, factor);
    EXPECT_GT(factor, 3.0) << sigma;
  }
}

}  // namespace
}  // namespace frusta
