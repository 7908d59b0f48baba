// SPDX-License-Identifier: MIT
// Shared by the hand-worked geometry tests: a segment whose angles are exact ratios,
// so cases need no trigonometry, and a vector comparison.
#pragma once

#include <gtest/gtest.h>

#include "geometry/types.h"

namespace frusta {

// E at the origin, D = (0.04, 0, 0), r2 = 3 mm, r1 = 12 mm: L : (r1 - r2) : side is
// 40 : 9 : 41, so cos(alpha) = 40/41 and sin(alpha) = 9/41.
inline Segment cone_9_40_41() { return {{0.04, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.012, 0.003}; }
constexpr double kCos = 40.0 / 41.0, kSin = 9.0 / 41.0;

inline void expect_vec_near(const vec3& a, const vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace frusta
