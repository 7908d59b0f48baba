// SPDX-License-Identifier: MIT
#include "solver/qp.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base.h"

namespace frusta {

namespace {

using Vec = std::array<double, kMaxQpVariables>;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double dot(int n, const Vec& a, const Vec& b) {
  double s = 0.0;
  for (int j = 0; j < n; ++j) s += a[j] * b[j];
  return s;
}

// The active set: unit normals (in scaled variables) and multipliers. With G = I after
// scaling, the primal step is n_p with its part in the active normals' span removed
// and the dual step the coefficients of that part, both from the small Gram system.
struct ActiveSet {
  int size = 0;
  // the first `size` of each (left unset until then: zeroing them was 3 % of a QP)
  std::array<int32_t, kMaxQpVariables> row;
  std::array<Vec, kMaxQpVariables> normal;
  std::array<double, kMaxQpVariables> u;

  // z = np - N r with (N^T N) r = N^T np; false when the Gram matrix is singular
  bool split(int n, const Vec& np, Vec& z, Vec& r) const {
    double gram[kMaxQpVariables][kMaxQpVariables];
    double rhs[kMaxQpVariables];
    for (int i = 0; i < size; ++i) {
      for (int k = 0; k <= i; ++k) gram[i][k] = dot(n, normal[i], normal[k]);
      rhs[i] = dot(n, normal[i], np);
    }
    // Cholesky in place, lower triangle
    for (int i = 0; i < size; ++i) {
      for (int k = 0; k <= i; ++k) {
        double s = gram[i][k];
        for (int m = 0; m < k; ++m) s -= gram[i][m] * gram[k][m];
        if (i == k) {
          if (!(s > 1e-24 * gram[i][i] + 1e-300)) return false;
          gram[i][i] = std::sqrt(s);
        } else {
          gram[i][k] = s / gram[k][k];
        }
      }
    }
    for (int i = 0; i < size; ++i) {
      double s = rhs[i];
      for (int m = 0; m < i; ++m) s -= gram[i][m] * r[m];
      r[i] = s / gram[i][i];
    }
    for (int i = size - 1; i >= 0; --i) {
      double s = r[i];
      for (int m = i + 1; m < size; ++m) s -= gram[m][i] * r[m];
      r[i] = s / gram[i][i];
    }
    z = np;
    for (int i = 0; i < size; ++i)
      for (int j = 0; j < n; ++j) z[j] -= r[i] * normal[i][j];
    return true;
  }

  void drop(int k) {
    for (int i = k; i + 1 < size; ++i) {
      row[i] = row[i + 1];
      normal[i] = normal[i + 1];
      u[i] = u[i + 1];
    }
    --size;
  }
};

// The solve for kN variables, or for `variables` when kN is 0. Known when compiled (a
// finger's QP has 4, the palm's 6), its loops over the variables unroll: the finger QPs
// of the 10^4-leaf grasp's closing steps took 21 % fewer instructions. The same
// operations in the same order either way, so the same answer to the bit.
template <int kN>
QpResult solve(int variables, const double* weights, const double* target, QpRow* rows,
               int32_t row_count, int32_t iteration_cap, double* x, QpLazyRows lazy) {
  const int n = kN > 0 ? kN : variables;
  QpResult result;
  // scale to y_j = sqrt(w_j) x_j so the objective is half the squared distance to the
  // target; with unit normals a row's slack is its distance, whatever its units
  Vec scale{}, y{};
  for (int j = 0; j < n; ++j) {
    scale[j] = 1.0 / std::sqrt(weights[j]);
    y[j] = target[j] / scale[j];
  }
  auto scale_row = [&](QpRow& row) {
    for (int j = 0; j < n; ++j) row.a[j] *= scale[j];
    row.active = false;
    row.unit = false;
  };
  for (int32_t i = 0; i < row_count; ++i) scale_row(rows[i]);
  const int32_t row_limit = row_count + std::max(0, lazy.rows_at ? lazy.capacity : 0);
  // A row is made unit the first time it is found violated (most never are): its slack
  // per unit normal is its raw slack over the normal's length, which has the raw one's
  // sign, so a row that holds raw holds made unit too (to rounding, a millionth of the
  // tolerance below)
  auto violated = [&](QpRow& row) {
    if (row.unit) return true;
    if (dot(n, row.a, y) - row.b >= 0.0) return false;
    const double length = std::sqrt(dot(n, row.a, row.a));
    if (!(length > 0.0)) {  // no normal: it holds or not whatever x is; ignore it
      row.active = true;
      return false;
    }
    for (int j = 0; j < n; ++j) row.a[j] /= length;
    row.b /= length;
    row.unit = true;
    return true;
  };
  ActiveSet active;
  auto finish = [&](QpStatus status) {
    result.status = status;
    result.rows = row_count;
    result.active = active.size;
    for (int k = 0; k < active.size; ++k) result.active_rows[static_cast<size_t>(k)] = active.row[k];
    for (int j = 0; j < n; ++j) x[j] = y[j] * scale[j];
    return result;
  };

  // how far a row's slack may fall below zero and still count as holding (rounding)
  auto tolerance = [](const QpRow& row) { return 1e-12 * (1.0 + std::fabs(row.b)); };
  auto beyond_tolerance = [&](QpRow& row, double& slack) {
    if (!violated(row)) return false;
    slack = dot(n, row.a, y) - row.b;
    return slack < -tolerance(row);
  };
  for (;;) {
    // the most violated row, a preferred one if any is violated
    int32_t p = -1;
    double worst = 0.0;
    bool preferred = false;
    for (int32_t i = 0; i < row_count; ++i) {
      double slack = 0.0;
      if (rows[i].active || (preferred && !rows[i].preferred) || !beyond_tolerance(rows[i], slack))
        continue;
      if ((rows[i].preferred && !preferred) || slack < worst - tolerance(rows[i])) {
        worst = slack;
        p = i;
        preferred = rows[i].preferred;
      }
    }
    // every listed row holds: the most violated of the lazy rows this point lies beyond,
    // if any (a row listed already holds here, so one found violated is new)
    if (p < 0 && row_count < row_limit) {
      Vec at{};
      for (int j = 0; j < n; ++j) at[j] = y[j] * scale[j];
      auto append_most_violated = [&](QpRow* made) {
        const int32_t count =
            std::min(lazy.rows_at(lazy.context, at.data(), made), kMaxLazyRowsAtOnce);
        int32_t most = -1;
        for (int32_t k = 0; k < count; ++k) {
          double slack = 0.0;
          scale_row(made[k]);
          if (beyond_tolerance(made[k], slack) && slack < worst) {
            worst = slack;
            most = k;
          }
        }
        if (most >= 0) {
          rows[row_count] = made[most];
          p = row_count++;
        }
      };
      // made where the next row goes while there is room for as many as a point may lie
      // beyond (a local array of them, zeroed at each ask, was 8 % of a QP's time)
      if (row_limit - row_count >= kMaxLazyRowsAtOnce) {
        append_most_violated(rows + row_count);
      } else {
        QpRow made[kMaxLazyRowsAtOnce];
        append_most_violated(made);
      }
    }
    if (p < 0) break;  // every row holds: optimal
    const Vec& np = rows[p].a;

    double u_p = 0.0;
    for (;;) {
      if (result.iterations >= iteration_cap) return finish(QpStatus::kIterationCap);
      ++result.iterations;
      Vec z{}, r{};
      if (!active.split(n, np, z, r)) return finish(QpStatus::kInfeasible);  // dependent normals
      // dual step limit: the first active multiplier to reach zero
      double t1 = kInfinity;
      int drop = -1;
      for (int k = 0; k < active.size; ++k)
        if (r[k] > 0.0 && active.u[k] / r[k] < t1) {
          t1 = active.u[k] / r[k];
          drop = k;
        }
      // primal step: the length that satisfies row p. With n rows active their normals
      // span every direction, so z is zero (rounding leaves a speck of it, which once
      // took a seventh row into a set of six): only a dual step is left
      const bool full = active.size >= n;
      const double zz = dot(n, z, np);
      const double violation = dot(n, np, y) - rows[p].b;
      const double t2 = !full && zz > 1e-20 * dot(n, np, np) ? -violation / zz : kInfinity;
      if (t1 == kInfinity && t2 == kInfinity) return finish(QpStatus::kInfeasible);
      const double t = t2 < t1 ? t2 : t1;
      if (t2 != kInfinity)
        for (int j = 0; j < n; ++j) y[j] += t * z[j];
      for (int k = 0; k < active.size; ++k) active.u[k] -= t * r[k];
      u_p += t;
      if (t2 <= t1) {  // row p holds now: it joins the active set
        rows[p].active = true;
        active.row[active.size] = p;
        active.normal[active.size] = np;
        active.u[active.size] = u_p;
        ++active.size;
        break;
      }
      rows[active.row[drop]].active = false;
      active.drop(drop);  // a multiplier reached zero: that row lets go
    }
  }
  return finish(QpStatus::kOptimal);
}

}  // namespace

QpResult solve_projection_qp(int n, const double* weights, const double* target, QpRow* rows,
                             int32_t row_count, int32_t iteration_cap, double* x, QpLazyRows lazy) {
  switch (n) {
    case FRUSTA_JOINTS_PER_FINGER:
      return solve<FRUSTA_JOINTS_PER_FINGER>(n, weights, target, rows, row_count, iteration_cap, x,
                                             lazy);
    case kMaxQpVariables:
      return solve<kMaxQpVariables>(n, weights, target, rows, row_count, iteration_cap, x, lazy);
    default:
      return solve<0>(n, weights, target, rows, row_count, iteration_cap, x, lazy);
  }
}

void QpHints::keep(const QpRow* rows, const QpResult& result) {
  count = 0;
  for (int32_t k = 0; k < result.active; ++k) {
    const int64_t key = rows[result.active_rows[static_cast<size_t>(k)]].key;
    if (key != 0) keys[static_cast<size_t>(count++)] = key;
  }
}

void QpHints::mark(QpRow* rows, int32_t row_count) const {
  for (int32_t i = 0; i < row_count; ++i) rows[i].preferred = rows[i].key != 0 && names(rows[i].key);
}

}  // namespace frusta
