// SPDX-License-Identifier: MIT
// An independent reference for the segment solid's distance, sharing no code with
// native/src/geometry: the frustum is the union of its axial disks, so the distance to
// it is the minimum over x in [0, L] of the 3-D point-to-disk distance f(x).
//
// Sampling bound. f(x) = sqrt(h(x)^2 + max(0, rho(x) - r(x))^2) with h, rho - r affine
// in x: a norm of (affine, convex non-negative), hence convex, and Lipschitz with
// constant sqrt(1 + tan^2 alpha). Sampling a grid of step s over an interval that holds
// a minimiser gives a value at most sqrt(1 + tan^2 alpha) * s / 2 above the minimum, and
// never below it (every sample is the distance to a subset of the solid). Convexity
// lets the grid be refined around the best sample (the minimiser lies between its two
// neighbours), so the step, and with it the bound, shrinks geometrically.
//
// Inside the frustum, the depth is the distance to its boundary: the two cap disks and
// the lateral surface, the union of the rim circles, whose distance
// sqrt(h^2 + (rho - r)^2) is convex in x with the same constant.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/types.h"

namespace frusta::reference {

struct ConvexMinimum {
  double value;      // smallest sample: >= the true minimum
  double tolerance;  // the true minimum is >= value - tolerance (exact arithmetic)
};

// Minimum of a convex f on [lo, hi] with Lipschitz constant lipschitz, to within target.
template <class F>
ConvexMinimum minimise_convex(const F& f, double lo, double hi, double lipschitz,
                              double target) {
  constexpr int kIntervals = 16;
  double best = f(lo);
  double step = (hi - lo) / kIntervals;
  for (int round = 0; round < 64; ++round) {
    double samples[kIntervals + 1];
    int arg = 0;
    for (int i = 0; i <= kIntervals; ++i) {
      samples[i] = f(i == kIntervals ? hi : lo + i * step);
      if (samples[i] < samples[arg]) arg = i;
    }
    best = std::min(best, samples[arg]);
    if (lipschitz * step * 0.5 <= target || step <= 0.0) break;
    // the minimiser lies between the best sample's neighbours
    const double new_lo = lo + std::max(arg - 1, 0) * step;
    const double new_hi = arg + 1 >= kIntervals ? hi : lo + (arg + 1) * step;
    lo = new_lo;
    hi = new_hi;
    const double new_step = (hi - lo) / kIntervals;
    if (!(new_step < step)) break;  // no progress left at this precision
    step = new_step;
  }
  return {best, lipschitz * step * 0.5};
}

struct BruteForce {
  double distance = 0.0;   // signed gap, the same semantics as exact_distance
  double tolerance = 0.0;  // |distance - true signed gap| <= tolerance, in exact arithmetic
  bool outside = false;    // the centre is outside every part: distance is an upper bound
  Feature nearest = Feature::kSide;
  double runner_up = 0.0;  // signed gap of the second-nearest part
};

namespace detail {
inline double norm(const vec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
inline double dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
}  // namespace detail

// target: sampling precision in metres (the tolerance is about this, not above it)
inline BruteForce brute_force_gap(const Segment& segment, const Sphere& sphere,
                                  double target = 1e-11) {
  using detail::dot;
  using detail::norm;
  // local coordinates with E at the origin: the far offset cancels exactly here
  const vec3 p = sphere.center - segment.distal;
  const vec3 d = segment.proximal - segment.distal;
  const double r1 = segment.proximal_radius, r2 = segment.distal_radius, R = sphere.radius;
  const double L = norm(d);

  double part[3];  // signed distance of the centre to frustum, distal ball, proximal ball
  double tol[3] = {0.0, 0.0, 0.0};
  bool inside_any = false;
  part[1] = norm(p) - r2;
  part[2] = norm(p - d) - r1;
  part[0] = HUGE_VAL;
  if (part[1] <= 0.0 || part[2] <= 0.0) inside_any = true;

  if (L > 0.0) {
    const vec3 u = d / L;
    const double slope = (r1 - r2) / L;
    const double lipschitz = std::sqrt(1.0 + slope * slope);
    auto radius_at = [&](double x) { return r2 + (r1 - r2) * (x / L); };
    // the disk and rim at axial position x: centre x u, normal u, radius r(x)
    auto to_disk = [&](double x) {
      const vec3 v = p - x * u;
      const double h = dot(v, u);
      const double rho = norm(v - h * u);
      const double excess = std::max(0.0, rho - radius_at(x));
      return std::sqrt(h * h + excess * excess);
    };
    auto to_rim = [&](double x) {
      const vec3 v = p - x * u;
      const double h = dot(v, u);
      const double rho = norm(v - h * u);
      const double e = rho - radius_at(x);
      return std::sqrt(h * h + e * e);
    };
    const double a = dot(p, u);
    const double q = norm(p - a * u);
    const bool inside = a >= 0.0 && a <= L && q <= radius_at(a);
    if (!inside) {
      const ConvexMinimum m = minimise_convex(to_disk, 0.0, L, lipschitz, target);
      part[0] = m.value;
      tol[0] = m.tolerance;
    } else {
      inside_any = true;
      const ConvexMinimum m = minimise_convex(to_rim, 0.0, L, lipschitz, target);
      const double depth = std::min({to_disk(0.0), to_disk(L), m.value});
      part[0] = -depth;
      tol[0] = m.tolerance;
    }
  }

  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (part[i] < part[best]) best = i;
  int second = best == 0 ? 1 : 0;
  for (int i = 0; i < 3; ++i)
    if (i != best && part[i] < part[second]) second = i;

  BruteForce out;
  out.distance = part[best] - R;
  out.runner_up = part[second] - R;
  out.tolerance = std::max({tol[0], tol[1], tol[2]});
  out.outside = !inside_any;
  out.nearest = best == 0 ? Feature::kSide : best == 1 ? Feature::kDistalBall : Feature::kProximalBall;
  return out;
}

}  // namespace frusta::reference
