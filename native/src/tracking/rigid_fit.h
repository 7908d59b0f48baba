// SPDX-License-Identifier: MIT
// The weighted least-squares rigid motion between two sets of points, with pairs of
// orientations joining in (Horn's closed form, "Closed-form solution of absolute
// orientation using unit quaternions", JOSA A 4(4), 1987): the palm's fit.
#pragma once

#include <array>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "geometry/types.h"

namespace frusta {

class RigidFit {
 public:
  static constexpr int kCapacity = 16;  // pairs of each kind

  // A model point and where it was measured, weight > 0.
  void add_point(const vec3& model, const vec3& measured, double weight);
  // A model frame's axes (columns) and the measured ones, weight > 0 (square metres:
  // each axis weighs like a point at sqrt(weight) metres).
  void add_axes(const glm::dmat3& model, const glm::dmat3& measured, double weight);

  int point_count() const { return points_; }
  int axes_count() const { return axes_; }

  // Whether the points alone fix the rotation: three or more, not in a line.
  bool points_fix_rotation() const;

  // The motion minimising sum w |R m + t - p|^2 + sum w ||R A - B||^2 over what was
  // added; needs a point (for t) and a fixed rotation (points_fix_rotation, or axes).
  void solve(glm::dquat* rotation, vec3* translation) const;

 private:
  std::array<vec3, kCapacity> model_{}, measured_{};
  std::array<double, kCapacity> weight_{};
  std::array<glm::dmat3, kCapacity> model_axes_{}, measured_axes_{};
  std::array<double, kCapacity> axes_weight_{};
  int points_ = 0;
  int axes_ = 0;
};

// Eigenvalues (descending) and the unit eigenvector of the largest of a symmetric 4x4
// matrix (cyclic Jacobi); returns the sweeps it took.
int symmetric_eigen4(const double matrix[4][4], double eigenvalues[4], double top_vector[4]);

}  // namespace frusta
