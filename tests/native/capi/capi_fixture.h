// SPDX-License-Identifier: MIT
// Shared by the C ABI tests: a fixture that fails any test leaving an unexpected
// error message behind, an RAII owner for hand ids, and random hand inputs.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

#include "core/error.h"
#include "frusta/frusta.h"

namespace frusta::testing {

// The message is thread-local and survives successful calls (like errno), so it is
// cleared before each test; any message still set at the end is a failure nobody
// checked. Expected failures go through ExpectError(), which consumes the message.
class CapiTest : public ::testing::Test {
 protected:
  void SetUp() override { clear_last_error(); }
  void TearDown() override {
    const std::string message = frusta_last_error();
    if (!message.empty()) ADD_FAILURE() << "unexpected frusta_last_error(): " << message;
  }

  // got == want and the message names `needle`; then the message is cleared.
  static void ExpectError(frusta_result got, frusta_result want, const char* needle) {
    const std::string message = frusta_last_error();
    EXPECT_EQ(got, want) << frusta_result_name(got) << ": " << message;
    EXPECT_NE(message.find(needle), std::string::npos)
        << "message \"" << message << "\" does not name " << needle;
    clear_last_error();
  }
};

// Owns a standalone hand; the test fails if creation fails.
class ScopedHand {
 public:
  explicit ScopedHand(const frusta_hand_def& def) {
    const frusta_result r = frusta_create_hand(&def, &id_);
    EXPECT_EQ(r, FRUSTA_OK) << frusta_last_error();
  }
  ~ScopedHand() {
    if (!FRUSTA_IS_NULL(id_)) frusta_destroy_hand(id_);
  }
  ScopedHand(const ScopedHand&) = delete;
  ScopedHand& operator=(const ScopedHand&) = delete;
  frusta_hand_id get() const { return id_; }

 private:
  frusta_hand_id id_{};
};

using Angles = std::array<double, FRUSTA_HAND_JOINT_COUNT>;

// angles inside the limits, at least a tenth of each range away from either end
inline Angles interior_angles(const frusta_hand_def& def, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.1, 0.9);
  Angles a{};
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
      a[f * 4 + j] = def.joint_min[f][j] + unit(rng) * (def.joint_max[f][j] - def.joint_min[f][j]);
  return a;
}

// a random pose: position within a metre, a uniformly random unit quaternion (x, y, z, w)
inline frusta_pose random_pose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::normal_distribution<double> gauss;
  frusta_pose p{};
  for (double& x : p.position) x = coord(rng);
  double norm = 0.0;
  for (double& q : p.rotation) {
    q = gauss(rng);
    norm += q * q;
  }
  for (double& q : p.rotation) q /= std::sqrt(norm);
  return p;
}

}  // namespace frusta::testing
