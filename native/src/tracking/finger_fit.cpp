// SPDX-License-Identifier: MIT
#include "tracking/finger_fit.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

namespace {

constexpr double kPi = 3.14159265358979323846;
// a refining step this small (radians) has converged: far below any tracker's noise
// (a fiftieth of a degree for 2 mm), where Gauss-Newton gains a digit an iteration; on
// exact joints it converges quadratically, and the step after it is rounding
constexpr double kConverged = 1e-5;
// Levenberg-Marquardt damping: start, and where a step that never lowers the cost stops
constexpr double kInitialDamping = 1e-3;
constexpr double kMaxDamping = 1e10;
// m^2/rad: a gradient this small is rounding, not a pull beyond a limit
constexpr double kNoPull = 1e-12;

using Points = std::array<vec3, 3>;
using Jacobian = std::array<std::array<vec3, 4>, 3>;  // [point][angle]

double wrap(double angle) { return std::remainder(angle, 2.0 * kPi); }

// the in-plane angle of a bone from (a0, c0) to (a1, c1): positive flexion turns the
// finger's +a towards -c (the palm)
double bone_angle(double da, double dc) { return std::atan2(-dc, da); }

// Chain points 1..3 at angles q, in the rest frame, and their derivatives: the
// abduction turns everything about z, flexion j turns bones j - 1.. in the plane
void chain_forward(const FingerChain& chain, const std::array<double, 4>& q, Points& points,
                   Jacobian* jacobian) {
  const vec3 along(std::cos(q[0]), std::sin(q[0]), 0.0), up(0.0, 0.0, 1.0);
  std::array<vec3, 3> bone{}, turn{};  // each bone's unit vector and its derivative
  double phi = 0.0;
  for (int s = 0; s < 3; ++s) {
    phi += q[static_cast<size_t>(1 + s)];
    bone[static_cast<size_t>(s)] = std::cos(phi) * along - std::sin(phi) * up;
    turn[static_cast<size_t>(s)] = -std::sin(phi) * along - std::cos(phi) * up;
  }
  vec3 point(0.0);
  for (int k = 0; k < 3; ++k) {
    point += chain.length[static_cast<size_t>(k)] * bone[static_cast<size_t>(k)];
    points[static_cast<size_t>(k)] = point;
  }
  if (!jacobian) return;
  for (int k = 0; k < 3; ++k) {
    auto& row = (*jacobian)[static_cast<size_t>(k)];
    const vec3& p = points[static_cast<size_t>(k)];
    row[0] = vec3(-p.y, p.x, 0.0);
    for (int j = 1; j < 4; ++j) {
      vec3 sum(0.0);
      for (int s = j - 1; s <= k; ++s)
        sum += chain.length[static_cast<size_t>(s)] * turn[static_cast<size_t>(s)];
      row[static_cast<size_t>(j)] = sum;
    }
  }
}

double squared_error(const FingerChain& chain, const FingerPoints& target,
                     const std::array<double, 4>& q) {
  Points p;
  chain_forward(chain, q, p, nullptr);
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
    if (target.present[static_cast<size_t>(k)]) {
      const vec3 d = p[static_cast<size_t>(k)] - target.point[static_cast<size_t>(k)];
      sum += glm::dot(d, d);
    }
  return sum;
}

// The finger's plane: the present points project onto a line through the first joint
// along (cos a, sin a). Of the line's two directions, the one nearer the middle of the
// abduction range; the last value where the points stand on the z axis.
double abduction_guess(const FingerChain& chain, const FingerPoints& points, double last) {
  double sxx = 0.0, sxy = 0.0, syy = 0.0, size = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (!points.present[static_cast<size_t>(k)]) continue;
    const vec3& p = points.point[static_cast<size_t>(k)];
    sxx += p.x * p.x;
    sxy += p.x * p.y;
    syy += p.y * p.y;
    size += glm::dot(p, p);
  }
  const double half_trace = 0.5 * (sxx + syy);
  const double largest = half_trace + std::hypot(0.5 * (sxx - syy), sxy);
  if (!(largest > 1e-12 * size)) return last;
  const double line = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const double middle = 0.5 * (chain.joint_min[0] + chain.joint_max[0]);
  return std::fabs(wrap(line - middle)) <= 0.5 * kPi ? wrap(line) : wrap(line + kPi);
}

// Of a bend and its twin the other way (which put the joint beyond in the same
// place), the one within the limits, or both being, the nearer the last fit's.
double twin_bend(const FingerChain& chain, int joint, double bend, double last) {
  auto outside = [&](double a) {
    return std::max({chain.joint_min[static_cast<size_t>(joint)] - a,
                     a - chain.joint_max[static_cast<size_t>(joint)], 0.0});
  };
  const double score_plus = outside(bend), score_minus = outside(-bend);
  if (score_plus != score_minus) return score_plus < score_minus ? bend : -bend;
  return std::fabs(bend - last) <= std::fabs(-bend - last) ? bend : -bend;
}

// Angles from the present points by geometry alone: in the plane, a bone between two
// present joints has its direction; across one missing joint the two bones are solved
// from the distance (twin_bend picks the bend's sign).
std::array<double, 4> analytic_guess(const FingerChain& chain, const FingerPoints& points,
                                     const std::array<double, 4>& last, int last_present) {
  std::array<double, 4> q = last;
  q[0] = abduction_guess(chain, points, last[0]);
  const double ca = std::cos(q[0]), sa = std::sin(q[0]);
  std::array<double, 3> phi{};  // each bone's angle in the plane
  int previous = -1;            // the chain point before: -1 is the first joint
  double pa = 0.0, pc = 0.0;
  for (int k = 0; k <= last_present; ++k) {
    if (!points.present[static_cast<size_t>(k)]) continue;
    const vec3& p = points.point[static_cast<size_t>(k)];
    const double a = ca * p.x + sa * p.y, c = p.z;
    const double direct = bone_angle(a - pa, c - pc);
    assert(k - previous <= 2);  // two present points leave at most one joint missing
    if (k - previous == 1) {
      phi[static_cast<size_t>(k)] = direct;
    } else {  // two bones, k - 1 and k, across a missing joint
      const double l1 = chain.length[static_cast<size_t>(k - 1)];
      const double l2 = chain.length[static_cast<size_t>(k)];
      const double d2 = (a - pa) * (a - pa) + (c - pc) * (c - pc);
      const double cosine = std::clamp((d2 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2), -1.0, 1.0);
      const double bend = twin_bend(chain, k + 1, std::acos(cosine), last[static_cast<size_t>(k + 1)]);
      phi[static_cast<size_t>(k - 1)] =
          direct - std::atan2(l2 * std::sin(bend), l1 + l2 * std::cos(bend));
      phi[static_cast<size_t>(k)] = phi[static_cast<size_t>(k - 1)] + bend;
    }
    previous = k;
    pa = a;
    pc = c;
  }
  for (int j = 1; j <= last_present + 1; ++j)
    q[static_cast<size_t>(j)] =
        wrap(phi[static_cast<size_t>(j - 1)] - (j > 1 ? phi[static_cast<size_t>(j - 2)] : 0.0));
  return q;
}

// Solve (A + damping) x = b for the n x n symmetric positive definite A (Cholesky).
void solve_damped(double a[4][4], const double b[4], int n, double x[4]) {
  double l[4][4] = {};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) {
      double sum = a[i][j];
      for (int k = 0; k < j; ++k) sum -= l[i][k] * l[j][k];
      l[i][j] = i == j ? std::sqrt(std::max(sum, 1e-300)) : sum / l[j][j];
    }
  }
  double y[4];
  for (int i = 0; i < n; ++i) {
    double sum = b[i];
    for (int k = 0; k < i; ++k) sum -= l[i][k] * y[k];
    y[i] = sum / l[i][i];
  }
  for (int i = n - 1; i >= 0; --i) {
    double sum = y[i];
    for (int k = i + 1; k < n; ++k) sum -= l[k][i] * x[k];
    x[i] = sum / l[i][i];
  }
}

}  // namespace

FingerChain finger_chain(const FingerModel& finger) {
  FingerChain chain;
  for (int s = 0; s < 3; ++s) chain.length[static_cast<size_t>(s)] = finger.length[static_cast<size_t>(s)];
  chain.length[2] += finger.radius[3];  // to the fingertip's end
  chain.joint_min = finger.joint_min;
  chain.joint_max = finger.joint_max;
  return chain;
}

double finger_residual(const FingerChain& chain, const FingerPoints& points,
                       const std::array<double, 4>& angles) {
  const int n = static_cast<int>(std::count(points.present.begin(), points.present.end(), true));
  return n == 0 ? 0.0 : std::sqrt(squared_error(chain, points, angles) / n);
}

FingerFitResult fit_finger(const FingerChain& chain, const FingerPoints& points,
                           const std::array<double, 4>& last, int max_iterations) {
  FingerFitResult out;
  int present = 0, last_present = -1;
  for (int k = 0; k < 3; ++k)
    if (points.present[static_cast<size_t>(k)]) {
      ++present;
      last_present = k;
    }
  if (present < 2) {
    out.angles = last;
    out.flags = FRUSTA_FIT_HELD;
    out.residual = finger_residual(chain, points, last);
    return out;
  }
  if (last_present < 2) out.flags |= FRUSTA_FIT_PARTIAL;
  // the angles the points determine: abduction and the flexions up to the last point
  const int free = last_present + 2;

  std::array<double, 4> q = analytic_guess(chain, points, last, last_present);
  for (int j = 0; j < 4; ++j)
    q[static_cast<size_t>(j)] = std::clamp(q[static_cast<size_t>(j)], chain.joint_min[static_cast<size_t>(j)],
                                           chain.joint_max[static_cast<size_t>(j)]);
  double cost = squared_error(chain, points, q);
  double damping = kInitialDamping;
  double gradient[4] = {};
  for (int iteration = 0;; ++iteration) {
    // gradient and Gauss-Newton matrix of half the squared error at q
    Points p;
    Jacobian jac;
    chain_forward(chain, q, p, &jac);
    double normal[4][4] = {};
    for (int j = 0; j < 4; ++j) gradient[j] = 0.0;
    for (int k = 0; k < 3; ++k) {
      if (!points.present[static_cast<size_t>(k)]) continue;
      const vec3 r = p[static_cast<size_t>(k)] - points.point[static_cast<size_t>(k)];
      const auto& row = jac[static_cast<size_t>(k)];
      for (int i = 0; i < free; ++i) {
        gradient[i] += glm::dot(row[static_cast<size_t>(i)], r);
        for (int j = 0; j <= i; ++j) normal[i][j] += glm::dot(row[static_cast<size_t>(i)], row[static_cast<size_t>(j)]);
      }
    }
    if (iteration >= max_iterations) break;
    // an angle held at a limit by a gradient pushing beyond it stays out of the step
    int index[4], n = 0;
    for (int j = 0; j < free; ++j) {
      const bool at_min = q[static_cast<size_t>(j)] <= chain.joint_min[static_cast<size_t>(j)] && gradient[j] > 0.0;
      const bool at_max = q[static_cast<size_t>(j)] >= chain.joint_max[static_cast<size_t>(j)] && gradient[j] < 0.0;
      if (!at_min && !at_max) index[n++] = j;
    }
    if (n == 0) break;
    double trace = 0.0;
    for (int i = 0; i < n; ++i) trace += normal[index[i]][index[i]];
    bool accepted = false, converged = false;
    double largest_step = 0.0;
    while (!accepted && damping <= kMaxDamping) {
      double a[4][4], b[4], step[4];
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j <= i; ++j) {
          const int r = std::max(index[i], index[j]), c = std::min(index[i], index[j]);
          a[i][j] = a[j][i] = normal[r][c];
        }
        // Marquardt's scaling, floored: an angle no point moves gets no step
        a[i][i] += damping * std::max(a[i][i], 1e-12 * trace);
        b[i] = -gradient[index[i]];
      }
      solve_damped(a, b, n, step);
      std::array<double, 4> trial = q;
      largest_step = 0.0;
      for (int i = 0; i < n; ++i) {
        const size_t j = static_cast<size_t>(index[i]);
        trial[j] = std::clamp(q[j] + step[i], chain.joint_min[j], chain.joint_max[j]);
        largest_step = std::max(largest_step, std::fabs(trial[j] - q[j]));
      }
      if (largest_step < kConverged) {
        // converged: this last step, too small to test, is taken (on exact joints it
        // leaves rounding; on noisy ones a sliver of the next)
        q = trial;
        cost = squared_error(chain, points, q);
        converged = true;
        break;
      }
      const double trial_cost = squared_error(chain, points, trial);
      if (trial_cost < cost) {
        q = trial;
        cost = trial_cost;
        damping = std::max(damping * 0.1, 1e-12);
        accepted = true;
      } else {
        damping *= 10.0;
      }
    }
    if (converged || !accepted) break;  // or no step lowers the cost
  }
  // a limit holds an angle the points pull beyond
  for (int j = 0; j < free; ++j) {
    if ((q[static_cast<size_t>(j)] <= chain.joint_min[static_cast<size_t>(j)] && gradient[j] > kNoPull) ||
        (q[static_cast<size_t>(j)] >= chain.joint_max[static_cast<size_t>(j)] && gradient[j] < -kNoPull))
      out.flags |= FRUSTA_FIT_CLAMPED;
  }
  out.angles = q;
  out.residual = std::sqrt(cost / present);
  return out;
}

}  // namespace frusta
