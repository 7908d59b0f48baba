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

// A warm start (QpHints): the rows one solve ended with active, preferred in a solve of
// the same problem, join first. The answer is the one optimum (any violated row may join
// next), and it is found in fewer changes to the active set; rows the hints name that no
// longer bind, or bind no more, are let go as any other.
TEST(ProjectionQp, PreferringTheLastActiveRowsFindsTheSameOptimumSooner) {
  std::mt19937_64 rng(20261204);
  int64_t cold_iterations = 0, warm_iterations = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    Problem p = random_problem(rng);
    for (size_t i = 0; i < p.rows.size(); ++i) p.rows[i].key = static_cast<int64_t>(i) + 1;
    double cold[kMaxQpVariables] = {}, warm[kMaxQpVariables] = {};
    std::vector<QpRow> scratch = p.rows;
    const QpResult first = solve_projection_qp(p.n, p.weights, p.target, scratch.data(),
                                               static_cast<int32_t>(scratch.size()), 200, cold);
    ASSERT_EQ(first.status, QpStatus::kOptimal);
    QpHints hints;
    hints.keep(scratch.data(), first);
    ASSERT_EQ(hints.count, first.active);
    // the same problem, and one whose target moved (the hints then only a guess)
    for (double shift : {0.0, 0.3}) {
      std::vector<QpRow> again = p.rows;
      hints.mark(again.data(), static_cast<int32_t>(again.size()));
      Problem moved = p;
      for (int j = 0; j < p.n; ++j) moved.target[j] += shift * (j % 2 ? 1.0 : -1.0);
      double reference[kMaxQpVariables] = {};
      std::vector<QpRow> plain = p.rows;
      const QpResult r0 = solve_projection_qp(p.n, moved.weights, moved.target, plain.data(),
                                              static_cast<int32_t>(plain.size()), 200, reference);
      const QpResult r1 = solve_projection_qp(p.n, moved.weights, moved.target, again.data(),
                                              static_cast<int32_t>(again.size()), 200, warm);
      ASSERT_EQ(r1.status, QpStatus::kOptimal) << "trial " << trial;
      for (int j = 0; j < p.n; ++j) ASSERT_NEAR(warm[j], reference[j], 1e-9) << "trial " << trial;
      if (shift == 0.0) {
        cold_iterations += r0.iterations;
        warm_iterations += r1.iterations;
        EXPECT_LE(r1.iterations, r0.iterations) << "trial " << trial;
      }
    }
  }
  // 39 % fewer here (22,617 -> 13,885): a row preferred may still join, let go and join
  EXPECT_LT(4 * warm_iterations, 3 * cold_iterations) << warm_iterations << " vs " << cold_iterations;
}

// A bound sum_j c_j |x_j - centre_j| <= r and lower limits as lazy rows (QpLazyRows, as
// the stages' motion bounds and a finger's joint limits): the same optimum as with every
// row listed, rows made as the answers reach them, never one twice.
struct L1Bound {
  int n = 0;
  double c[kMaxQpVariables] = {}, centre[kMaxQpVariables] = {}, r = 0.0;
  QpRow face(int signs) const {  // sum_j s_j c_j (x_j - centre_j) <= r, s_j = -1 for bit j
    QpRow row;
    row.b = -r;
    for (int j = 0; j < n; ++j) {
      const double s = (signs >> j) & 1 ? -1.0 : 1.0;
      row.a[j] = -s * c[j];
      row.b -= s * c[j] * centre[j];
    }
    row.key = signs + 1;
    return row;
  }
  // and x_j >= low_j, as a finger's joint limits: several made at once where x passes them
  double low[kMaxQpVariables] = {};
  QpRow limit(int j) const {
    QpRow row;
    row.a[j] = 1.0;
    row.b = low[j];
    row.key = 1000 + j;
    return row;
  }
  static int32_t rows_at(const void* self, const double* x, QpRow* rows) {
    const L1Bound& b = *static_cast<const L1Bound*>(self);
    int32_t count = 0;
    int signs = 0;
    for (int j = 0; j < b.n; ++j) {
      if (x[j] - b.centre[j] < 0.0) signs |= 1 << j;
      if (x[j] < b.low[j]) rows[count++] = b.limit(j);
    }
    rows[count++] = b.face(signs);
    return count;
  }
};

TEST(ProjectionQp, LazyRowsGiveTheOptimumEveryRowListedGives) {
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int binding = 0;
  int64_t listed_rows = 0, lazy_rows = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Problem p = random_problem(rng);
    L1Bound bound;
    bound.n = p.n;
    for (int j = 0; j < p.n; ++j) {
      bound.c[j] = std::exp(unit(rng));
      bound.centre[j] = 0.2 * unit(rng);
      bound.low[j] = trial % 2 ? -1e9 : -0.3 - 0.5 * std::fabs(unit(rng));
    }
    // around the rows' feasible point often enough to meet them, sometimes infeasible
    bound.r = 0.05 + std::fabs(unit(rng));
    std::vector<QpRow> every = p.rows;
    for (int signs = 0; signs < (1 << p.n); ++signs) every.push_back(bound.face(signs));
    for (int j = 0; j < p.n; ++j) every.push_back(bound.limit(j));
    std::vector<QpRow> lazy = p.rows;
    lazy.resize(p.rows.size() + (size_t{1} << p.n) + static_cast<size_t>(p.n));
    double x_every[kMaxQpVariables] = {}, x_lazy[kMaxQpVariables] = {};
    const QpResult r_every = solve_projection_qp(p.n, p.weights, p.target, every.data(),
                                                 static_cast<int32_t>(every.size()), 400, x_every);
    const QpResult r_lazy = solve_projection_qp(p.n, p.weights, p.target, lazy.data(),
                                                static_cast<int32_t>(p.rows.size()), 400, x_lazy,
                                                {&L1Bound::rows_at, &bound, (1 << p.n) + p.n});
    ASSERT_EQ(r_lazy.status, r_every.status) << "trial " << trial;
    ASSERT_GE(r_lazy.rows, static_cast<int32_t>(p.rows.size()));
    std::vector<int64_t> keys;
    for (int32_t i = static_cast<int32_t>(p.rows.size()); i < r_lazy.rows; ++i)
      keys.push_back(lazy[i].key);
    std::sort(keys.begin(), keys.end());
    ASSERT_TRUE(std::adjacent_find(keys.begin(), keys.end()) == keys.end()) << "a row made twice";
    if (r_every.status != QpStatus::kOptimal) continue;
    for (int j = 0; j < p.n; ++j) ASSERT_NEAR(x_lazy[j], x_every[j], 1e-9) << "trial " << trial;
    double l1 = 0.0;
    for (int j = 0; j < p.n; ++j) {
      l1 += bound.c[j] * std::fabs(x_lazy[j] - bound.centre[j]);
      ASSERT_GE(x_lazy[j], bound.low[j] - 1e-9) << "trial " << trial;
    }
    ASSERT_LE(l1, bound.r * (1.0 + 1e-9) + 1e-12) << "trial " << trial;
    binding += !keys.empty();
    listed_rows += static_cast<int64_t>(every.size());
    lazy_rows += r_lazy.rows;
  }
  EXPECT_GT(binding, 2000) << "the bound should bind in many trials";
  EXPECT_LT(lazy_rows, listed_rows) << "faces made only where met";
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

// A palm QP met in a world (a dynamic cube of absurdly small mass, a palm swinging
// through it): seven rows on six variables, nearly dependent. Rounding left a speck of
// primal direction once all six were active, and the seventh row was appended past
// the active set's end (a stack overflow under ASan).
TEST(ProjectionQp, AFullActiveSetTakesNoSeventhRow) {
  const int n = 6;
  const double w[n] = {0x1p+0, 0x1p+0, 0x1p+0, 0x1.27bb2fec56d5dp-5, 0x1.27bb2fec56d5dp-5,
                       0x1.27bb2fec56d5dp-5};
  const double target[n] = {-0x1.86375c207408dp-8, 0x1.cf3a05e23680ep-10, 0x1.ef74c6b9ba0c3p-5,
                            0x1.c53e2f9936becp-9,  -0x1.201beead87e8ep-4, -0x1.03af0e3927582p-7};
  const double a[7][n + 1] = {
      {0x1.d9c159a25341fp-1, 0x1.c63fc7a66a457p-3, 0x1.0dd4a8828013ep-2, -0x1.11215727a885ap-5,
       -0x1.416d387048a7bp-5, 0x1.3369aef95c754p-3, 0x1.702c177ee1546p-11},
      {0x1.9fc3e16ad301ap-2, 0x1.83abed1dd589p-2, -0x1.a86a2f23b7837p-1, -0x1.707efb7572ee6p-6,
       0x1.fe1acc28ba40fp-5, 0x1.1d73311b0286p-6, 0x1.eb5900262f17ap-11},
      {0x1.19c2944577729p-2, 0x1.00ef2e4de5554p-4, -0x1.e98053e377058p-1, 0x1.c379f82063c72p-6,
       0x1.2ca1c1e698919p-4, 0x1.a1abdf6b70035p-7, 0x1.0e15b5098f122p-8},
      {-0x1.348cdaf1f6769p-2, 0x1.e341f486324a9p-1, 0x1.023366fd8c041p-3, -0x1.88713d0d8cc64p-8,
       -0x1.11eab93171e04p-7, 0x1.8b6e209c1f573p-5, 0x1.cad7ac2bc51ebp-8},
      {0x1.6aedfaf60b9dp-3, -0x1.f44131ebc224ap-1, -0x1.afa650f4b70c7p-4, 0x1.528ac2b109581p-7,
       0x1.e8de0838ee136p-8, -0x1.a83e68b97f912p-5, 0x1.cfa47f41ae24cp-7},
      {-0x1.a0e8f82447f1ep-1, -0x1.038d28f64e8c6p-1, -0x1.d9cb6ce1a5afap-3, 0x1.fae43051f34f1p-6,
       0x1.6fb0ec6dac6c3p-6, -0x1.43bad14f9b6bap-3, -0x1.fdaab57202cd6p-12},
      {-0x1.116a2457d9651p-6, -0x1.7096b86a5b64p-3, -0x1.d6541c105a45dp-1, 0x1.2aabdc0548596p-4,
       0x1.592e39de34836p-2, -0x1.13f029ca90979p-4, -0x1.a5e04f8f79567p-11}};
  QpRow rows[7];
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < n; ++j) rows[i].a[j] = a[i][j];
    rows[i].b = a[i][n];
  }
  double x[n] = {};
  const QpResult r = solve_projection_qp(n, w, target, rows, 7, 64, x);
  EXPECT_LE(r.active, n);
  for (double v : x) EXPECT_TRUE(std::isfinite(v));
}

// The same on random problems built to be nearly degenerate: more rows than variables,
// each a tiny perturbation of a few directions, every variable count.
TEST(ProjectionQp, NearlyDependentRowsNeverOverfillTheActiveSet) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int c = 0; c < 20000; ++c) {
    const int n = 1 + c % kMaxQpVariables;
    double w[kMaxQpVariables], target[kMaxQpVariables];
    for (int j = 0; j < n; ++j) {
      w[j] = std::exp(4.0 * unit(rng));
      target[j] = unit(rng);
    }
    const double spread = std::pow(10.0, -16.0 * std::fabs(unit(rng)));
    std::vector<QpRow> rows(static_cast<size_t>(n + 1 + c % 8));
    for (size_t i = 0; i < rows.size(); ++i) {
      const QpRow& base = rows[i % static_cast<size_t>(n)];
      for (int j = 0; j < n; ++j)
        rows[i].a[j] = i < static_cast<size_t>(n) ? unit(rng) : base.a[j] + spread * unit(rng);
      rows[i].b = 2.0 + unit(rng);  // every row cuts off the target region
    }
    double x[kMaxQpVariables] = {};
    const QpResult r = solve_projection_qp(n, w, target, rows.data(),
                                           static_cast<int32_t>(rows.size()), 64, x);
    ASSERT_LE(r.active, n) << "case " << c;
    for (int j = 0; j < n; ++j) ASSERT_TRUE(std::isfinite(x[j])) << "case " << c;
  }
}

}  // namespace
}  // namespace frusta
