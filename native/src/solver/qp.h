// SPDX-License-Identifier: MIT
// The small QP of every contact solve (seed eq. 6 under linearised eq. 9): a weighted
// projection, min 1/2 sum_j w_j (x_j - target_j)^2 subject to a_i . x >= b_i, with at
// most kMaxQpVariables unknowns and any number of rows. Solved by the dual active-set
// method of Goldfarb and Idnani (1983), which needs no feasible start and reports an
// infeasible problem instead of cycling, the two things a penetrating start needs.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace frusta {

constexpr int kMaxQpVariables = 6;

struct QpRow {
  std::array<double, kMaxQpVariables> a{};
  double b = 0.0;
  int64_t key = 0;         // the caller's name for the row (0: none); not read here
  int32_t source = -1;     // the caller's index of what it stands for; not read here
  bool preferred = false;  // the caller's guess that it binds: among rows violated, it joins first
  bool active = false;     // the solver's own marks
  bool unit = false;
};

enum class QpStatus : int { kOptimal = 0, kInfeasible = 1, kIterationCap = 2 };

struct QpResult {
  QpStatus status = QpStatus::kOptimal;
  int32_t iterations = 0;  // constraints added or dropped
  int32_t rows = 0;        // rows listed and appended (QpLazyRows)
  int32_t active = 0;      // rows active at the solution
  std::array<int32_t, kMaxQpVariables> active_rows{};  // their indices, the first `active`
};

// The rows a QP ended with active, by their keys: the next QP of a like problem (the
// next linearisation, the next step's) prefers them, adding them first instead of
// finding them again through rows that join and let go: the dual method's warm start.
// A guess only: which violated row joins next is the method's free choice.
struct QpHints {
  std::array<int64_t, kMaxQpVariables> keys{};
  int32_t count = 0;
  // how far the part's last stage moved in its first linearisation (step_motion): the
  // next one's first makes the rows a step of about that can reach (stage.h)
  double first_step = INFINITY;

  void keep(const QpRow* rows, const QpResult& result);
  // whether the last QP ended with the row of this key active
  bool names(int64_t key) const {
    for (int32_t k = 0; k < count; ++k)
      if (keys[static_cast<size_t>(k)] == key) return true;
    return false;
  }
  void mark(QpRow* rows, int32_t row_count) const;
};

// Rows made only where a point needs them: the faces of a bound such as sum_j |c_j x_j|
// <= r (2^n rows, of which a point meets at most one), bounds on single variables.
// rows_at(context, x, rows) writes up to kMaxLazyRowsAtOnce rows that x may lie beyond,
// each whole (every member: `rows` may hold old rows), and returns how many. The QP asks
// once no listed row is violated and appends the most violated of them, up to `capacity`
// rows in all.
constexpr int32_t kMaxLazyRowsAtOnce = kMaxQpVariables + 1;
struct QpLazyRows {
  int32_t (*rows_at)(const void* context, const double* x, QpRow* rows) = nullptr;
  const void* context = nullptr;
  int32_t capacity = 0;  // rows the array has room for beyond row_count
};

// x holds the solution on return (the best point reached when not optimal). The rows
// are rescaled in place (scaled variables; a row found violated to a unit normal) so
// each pass over them is a plain dot product; a row with a zero normal is dropped. Lazy
// rows are appended after row_count (QpResult::rows counts them too). Allocates nothing;
// rows are read in order, so equal inputs give equal outputs.
QpResult solve_projection_qp(int n, const double* weights, const double* target, QpRow* rows,
                             int32_t row_count, int32_t iteration_cap, double* x,
                             QpLazyRows lazy = {});

}  // namespace frusta
