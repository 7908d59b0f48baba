// SPDX-License-Identifier: MIT
#include "tracking/rigid_fit.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

namespace {

// below it, the second direction of the points is lost in rounding: a line
constexpr double kInLine = 1e-10;

}  // namespace

void RigidFit::add_point(const vec3& model, const vec3& measured, double weight) {
  assert(points_ < kCapacity && weight > 0.0);
  model_[static_cast<size_t>(points_)] = model;
  measured_[static_cast<size_t>(points_)] = measured;
  weight_[static_cast<size_t>(points_++)] = weight;
}

void RigidFit::add_axes(const glm::dmat3& model, const glm::dmat3& measured, double weight) {
  assert(axes_ < kCapacity && weight > 0.0);
  model_axes_[static_cast<size_t>(axes_)] = model;
  measured_axes_[static_cast<size_t>(axes_)] = measured;
  axes_weight_[static_cast<size_t>(axes_++)] = weight;
}

bool RigidFit::points_fix_rotation() const {
  if (points_ < 3) return false;
  // the model points' scatter has a second direction: its eigenvalues l1 >= l2 >= l3
  // give tr^2 - |S|^2 = 2 (l1 l2 + l1 l3 + l2 l3), about 2 l1 l2
  double total = 0.0;
  vec3 centre(0.0);
  for (int i = 0; i < points_; ++i) {
    total += weight_[static_cast<size_t>(i)];
    centre += weight_[static_cast<size_t>(i)] * model_[static_cast<size_t>(i)];
  }
  centre /= total;
  glm::dmat3 scatter(0.0);
  for (int i = 0; i < points_; ++i) {
    const vec3 d = model_[static_cast<size_t>(i)] - centre;
    scatter += weight_[static_cast<size_t>(i)] * glm::outerProduct(d, d);
  }
  const double trace = scatter[0][0] + scatter[1][1] + scatter[2][2];
  double frobenius = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) frobenius += scatter[c][r] * scatter[c][r];
  return 0.5 * (trace * trace - frobenius) > kInLine * trace * trace;
}

void RigidFit::solve(glm::dquat* rotation, vec3* translation) const {
  assert(points_ > 0);
  double total = 0.0;
  vec3 model_centre(0.0), measured_centre(0.0);
  for (int i = 0; i < points_; ++i) {
    const double w = weight_[static_cast<size_t>(i)];
    total += w;
    model_centre += w * model_[static_cast<size_t>(i)];
    measured_centre += w * measured_[static_cast<size_t>(i)];
  }
  model_centre /= total;
  measured_centre /= total;

  // cross-covariance s[a][b] = sum w m_a p_b, centred points, plus the axes' pairs
  double s[3][3] = {};
  for (int i = 0; i < points_; ++i) {
    const vec3 m = model_[static_cast<size_t>(i)] - model_centre;
    const vec3 p = measured_[static_cast<size_t>(i)] - measured_centre;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) s[a][b] += weight_[static_cast<size_t>(i)] * m[a] * p[b];
  }
  for (int i = 0; i < axes_; ++i) {
    const glm::dmat3& m = model_axes_[static_cast<size_t>(i)];
    const glm::dmat3& p = measured_axes_[static_cast<size_t>(i)];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) s[a][b] += axes_weight_[static_cast<size_t>(i)] * m[k][a] * p[k][b];
  }

  // Horn's symmetric matrix: its top eigenvector is the rotation (w, x, y, z)
  const double n[4][4] = {
      {s[0][0] + s[1][1] + s[2][2], s[1][2] - s[2][1], s[2][0] - s[0][2], s[0][1] - s[1][0]},
      {s[1][2] - s[2][1], s[0][0] - s[1][1] - s[2][2], s[0][1] + s[1][0], s[2][0] + s[0][2]},
      {s[2][0] - s[0][2], s[0][1] + s[1][0], -s[0][0] + s[1][1] - s[2][2], s[1][2] + s[2][1]},
      {s[0][1] - s[1][0], s[2][0] + s[0][2], s[1][2] + s[2][1], -s[0][0] - s[1][1] + s[2][2]}};
  double eigenvalues[4], q[4];
  symmetric_eigen4(n, eigenvalues, q);
  *rotation = glm::normalize(glm::dquat(q[0], q[1], q[2], q[3]));
  *translation = measured_centre - glm::mat3_cast(*rotation) * model_centre;
}

int symmetric_eigen4(const double matrix[4][4], double eigenvalues[4], double top_vector[4]) {
  double a[4][4], v[4][4];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = matrix[r][c];
      v[r][c] = r == c ? 1.0 : 0.0;
    }
  // cyclic Jacobi: rotate away each off-diagonal entry until none is left; quadratic
  // convergence, a handful of sweeps. An entry rounding cannot tell from zero beside
  // its diagonal is zero (Numerical Recipes' test), so the sweeps end.
  int sweep = 0;
  while (sweep < 50) {
    ++sweep;
    bool rotated = false;
    for (int p = 0; p < 3; ++p) {
      for (int q = p + 1; q < 4; ++q) {
        if (std::fabs(a[p][q]) <= 1e-17 * (std::fabs(a[p][p]) + std::fabs(a[q][q]))) {
          a[p][q] = a[q][p] = 0.0;
          continue;
        }
        rotated = true;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 4; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 4; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
    if (!rotated) break;
  }
  int order[4] = {0, 1, 2, 3};
  std::sort(order, order + 4, [&](int i, int j) { return a[i][i] > a[j][j]; });
  for (int k = 0; k < 4; ++k) eigenvalues[k] = a[order[k]][order[k]];
  for (int k = 0; k < 4; ++k) top_vector[k] = v[k][order[0]];
  return sweep;
}

}  // namespace frusta
