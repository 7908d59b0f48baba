// SPDX-License-Identifier: MIT
// Seeded random segment/sphere cases shared by the geometry tests and benchmarks.
// Every case names its family, so a failing property can say which kind of input
// broke it, and carries its index in the stream so it can be regenerated alone.
//
// Families: hand-like segments (L 1-6 cm, radii 0.5-1.2 cm, r1 >= r2) and the
// degenerate inputs the engine must survive: cylinder (r1 == r2), cone (r2 == 0),
// zero length (D == E), point sphere (R == 0), coordinates offset by ~1e6 m, centre on
// the axis, inverted radii (r1 < r2), very short segments (L 1e-7..1e-4 m) and spheres
// placed at a known signed gap of 1e-9..1e-3 m from the solid (boundary). Boundary
// cases carry that gap, computed by construction from the geometry alone (not by the
// code under test), so they are also an independent reference.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/types.h"

namespace frusta::scenes {

enum class Family : int {
  kHand = 0,       // hand-like segment, sphere anywhere near it
  kCylinder,       // r1 == r2
  kCone,           // r2 == 0
  kZeroLength,     // D == E exactly
  kPointSphere,    // R == 0
  kFarOffset,      // a hand case with every point moved by ~1e6 m
  kOnAxis,         // centre on the axis (exactly for axis-aligned segments)
  kInvertedRadii,  // r1 < r2
  kShortSegment,   // L from 1e-7 to 1e-4 m: huge slope, tiny cos(alpha)
  kBoundary,       // signed gap to the solid known by construction, |gap| in [1e-9, 1e-3]
  kCount
};

constexpr int kFamilyCount = static_cast<int>(Family::kCount);

inline const char* family_name(Family family) {
  switch (family) {
    case Family::kHand: return "hand";
    case Family::kCylinder: return "cylinder";
    case Family::kCone: return "cone";
    case Family::kZeroLength: return "zero_length";
    case Family::kPointSphere: return "point_sphere";
    case Family::kFarOffset: return "far_offset";
    case Family::kOnAxis: return "on_axis";
    case Family::kInvertedRadii: return "inverted_radii";
    case Family::kShortSegment: return "short_segment";
    case Family::kBoundary: return "boundary";
    case Family::kCount: break;
  }
  return "?";
}

inline const char* family_name(int family) { return family_name(static_cast<Family>(family)); }

struct Case {
  Segment segment;
  Sphere sphere;
  Family family = Family::kHand;
  std::uint64_t index = 0;  // position in its generator's stream
  vec3 offset{0.0};         // kFarOffset: added to D, E and O; subtract it for the origin case
  // kBoundary: signed gap between the sphere and the solid (frustum union both balls;
  // inside, the depth in the deepest single part), exact up to rounding. NaN otherwise.
  double expected_gap = std::numeric_limits<double>::quiet_NaN();
};

// Fixed seeds: a failure reproduces on every machine.
constexpr std::uint64_t kPropertySeed = 0x5eed'f257'aULL;
constexpr std::uint64_t kBenchmarkSeed = 0xbe9c'4a11ULL;

// How many random cases a property test runs: env FRUSTA_PROPERTY_CASES (the sanitizer
// run sets a smaller number), else one million.
inline std::uint64_t property_case_count(std::uint64_t fallback = 1000000) {
  const char* text = std::getenv("FRUSTA_PROPERTY_CASES");
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const unsigned long long n = std::strtoull(text, &end, 10);
  return (end != text && n > 0) ? static_cast<std::uint64_t>(n) : fallback;
}

// A property test's own count of random draws, `full` at the default million cases and
// scaled with property_case_count() (a tenth in the sanitizer run, more by hand), never
// below `least`: the first draws of the full run, the same at every scale.
inline int scaled_case_count(int full, int least) {
  const double scaled = std::min(full * static_cast<double>(property_case_count()) / 1e6,
                                 double{std::numeric_limits<int>::max()});
  return std::max(least, static_cast<int>(scaled));
}

// Which of a scripted test's cases run: every one, or with env FRUSTA_SCENARIO_STRIDE=k
// every k-th (the sanitizer run, where each case costs ~4x and the code is the same).
// A test runs its case i (in its own order) when scenario_runs(i).
inline std::uint64_t scenario_stride() {
  const char* text = std::getenv("FRUSTA_SCENARIO_STRIDE");
  if (text == nullptr || *text == '\0') return 1;
  char* end = nullptr;
  const unsigned long long k = std::strtoull(text, &end, 10);
  return (end != text && k > 0) ? static_cast<std::uint64_t>(k) : 1;
}
inline bool scenario_runs(std::uint64_t index) { return index % scenario_stride() == 0; }

class CaseGenerator {
 public:
  explicit CaseGenerator(std::uint64_t seed) : rng_(seed) {}

  // The next case of the mix (weights below; boundary and hand cases dominate).
  Case next() {
    static constexpr std::array<int, kFamilyCount> kWeights = {4, 1, 1, 1, 1, 1, 1, 1, 1, 3};
    int total = 0;
    for (int w : kWeights) total += w;
    int pick = std::uniform_int_distribution<int>(0, total - 1)(rng_);
    int family = 0;
    while (pick >= kWeights[static_cast<size_t>(family)]) pick -= kWeights[static_cast<size_t>(family++)];
    return make(static_cast<Family>(family));
  }

  // The next case of one family.
  Case make(Family family) {
    Case c;
    c.family = family;
    c.index = count_++;
    switch (family) {
      case Family::kHand: place_near(c, hand_shape()); break;
      case Family::kCylinder: {
        Shape s = hand_shape();
        s.r1 = s.r2;
        place_near(c, s);
        break;
      }
      case Family::kCone: {
        Shape s = hand_shape();
        s.r2 = 0.0;
        place_near(c, s);
        break;
      }
      case Family::kZeroLength: {
        Shape s = hand_shape();
        s.length = 0.0;
        if (coin()) std::swap(s.r1, s.r2);
        place_near(c, s);
        break;
      }
      case Family::kPointSphere: place_near(c, hand_shape(), /*point_sphere=*/true); break;
      case Family::kFarOffset: {
        place_near(c, hand_shape());
        for (int k = 0; k < 3; ++k) {
          // a whole number of metres: exactly representable, so subtracting it is exact
          const double magnitude = std::round(uniform(0.5e6, 2.0e6));
          c.offset[k] = coin() ? magnitude : -magnitude;
        }
        c.segment.proximal += c.offset;
        c.segment.distal += c.offset;
        c.sphere.center += c.offset;
        break;
      }
      case Family::kOnAxis: place_on_axis(c); break;
      case Family::kInvertedRadii: {
        Shape s = hand_shape();
        std::swap(s.r1, s.r2);
        if (s.r1 == s.r2) s.r1 *= 0.5;
        place_near(c, s);
        break;
      }
      case Family::kShortSegment: {
        Shape s = hand_shape();
        s.length = std::pow(10.0, uniform(-7.0, -4.0));
        place_near(c, s);
        break;
      }
      case Family::kBoundary: place_at_boundary(c); break;
      case Family::kCount: break;
    }
    return c;
  }

  std::mt19937_64& rng() { return rng_; }

 private:
  struct Shape {
    double length, r1, r2;
  };
  struct Basis {
    vec3 u, n1, n2;  // u along E -> D
  };

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool coin() { return (rng_() >> 63) != 0; }

  Shape hand_shape() {
    Shape s;
    s.length = uniform(0.01, 0.06);
    s.r1 = uniform(0.005, 0.012);
    s.r2 = uniform(0.005, s.r1);
    return s;
  }

  // object sphere radii from 0.3 mm sphere-tree leaves to 5 cm objects, log-uniform
  double object_radius() { return std::pow(10.0, uniform(-3.5, -1.3)); }

  vec3 random_unit() {
    std::normal_distribution<double> gauss;
    for (;;) {
      // braces: the draws in order on every compiler and architecture (the arguments of
      // a call have none: GCC draws z first on x86_64, x first on arm64)
      const vec3 v{gauss(rng_), gauss(rng_), gauss(rng_)};
      const double n = glm::length(v);
      if (n > 1e-6) return v / n;
    }
  }

  Basis random_basis() {
    Basis b;
    b.u = random_unit();
    const vec3 helper = std::fabs(b.u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    b.n1 = glm::normalize(glm::cross(b.u, helper));
    b.n2 = glm::cross(b.u, b.n1);
    return b;
  }

  vec3 random_distal() { return vec3{uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(-0.2, 0.2)}; }

  void set_segment(Case& c, const vec3& e, const Basis& b, const Shape& s) {
    c.segment.distal = e;
    c.segment.proximal = s.length > 0.0 ? e + s.length * b.u : e;
    c.segment.proximal_radius = s.r1;
    c.segment.distal_radius = s.r2;
  }

  // centre uniform in the segment's box grown by the largest radius, R and 1 cm
  void place_near(Case& c, const Shape& s, bool point_sphere = false) {
    const Basis b = random_basis();
    const vec3 e = random_distal();
    set_segment(c, e, b, s);
    const double radius = point_sphere ? 0.0 : object_radius();
    const double grow = std::max(s.r1, s.r2) + radius + 0.01;
    c.sphere.radius = radius;
    const double along = uniform(-grow, s.length + grow);  // one draw a statement: in order
    const double across1 = uniform(-grow, grow);
    const double across2 = uniform(-grow, grow);
    c.sphere.center = e + along * b.u + across1 * b.n1 + across2 * b.n2;
  }

  void place_on_axis(Case& c) {
    const Shape s = hand_shape();
    const vec3 e = random_distal();
    const double radius = object_radius();
    const double along = uniform(-(s.r2 + radius + 0.01), s.length + s.r1 + radius + 0.01);
    c.sphere.radius = radius;
    c.segment.distal = e;
    c.segment.proximal_radius = s.r1;
    c.segment.distal_radius = s.r2;
    if (coin()) {
      // axis-aligned: the centre's other two coordinates equal E's, so |OC| is exactly 0
      const int k = std::uniform_int_distribution<int>(0, 2)(rng_);
      const double sign = coin() ? 1.0 : -1.0;
      c.segment.proximal = e;
      c.segment.proximal[k] += sign * s.length;
      c.sphere.center = e;
      c.sphere.center[k] += sign * along;
    } else {
      // any direction: |OC| is zero up to rounding (~1e-17 m)
      const Basis b = random_basis();
      set_segment(c, e, b, s);
      c.sphere.center = e + (along / s.length) * (c.segment.proximal - e);
    }
  }

  // Put the sphere at a signed gap g, 1e-9 <= |g| <= 1e-3, from a point P of the solid's
  // surface along the surface normal there. Frustum: P on the side, whose nearest point
  // to O = P + d n (d >= 0) is P because the frustum is convex; inside (d < 0) its depth
  // is the smallest distance to its three edge lines. Balls: exact. A ball construction
  // is kept only when a lower bound of the frustum's distance (the largest signed
  // distance to its edge lines) shows the frustum is not nearer.
  void place_at_boundary(Case& c) {
    Shape s = hand_shape();
    const double variant = uniform(0.0, 1.0);
    if (variant < 0.15) s.r1 = s.r2;                  // cylinder
    else if (variant < 0.30) s.r2 = 0.0;              // cone
    else if (variant < 0.40) std::swap(s.r1, s.r2);   // inverted
    const Basis b = random_basis();
    const vec3 e = random_distal();
    set_segment(c, e, b, s);
    const double radius = uniform(0.0, 1.0) < 0.1 ? 0.0 : std::pow(10.0, uniform(-4.0, -1.3));
    c.sphere.radius = radius;

    const double L = s.length, r1 = s.r1, r2 = s.r2;
    const double side = std::hypot(L, r1 - r2);
    const double cos_a = L / side, sin_a = (r1 - r2) / side, slope = (r1 - r2) / L;
    // signed distance to the solid of a point (a, y) of the meridian half-plane, known
    // exactly when the frustum's signed distance is given; lower bound of the frustum's
    auto frustum_lower_bound = [&](double a, double y) {
      return std::max({-a, a - L, (y - r2 - a * slope) * cos_a});
    };
    auto ball_distances = [&](double a, double y) {
      return std::min(std::hypot(a, y) - r2, std::hypot(a - L, y) - r1);
    };

    for (int attempt = 0; attempt < 64; ++attempt) {
      const double sign = coin() ? 1.0 : -1.0;
      const double gap = sign * std::pow(10.0, uniform(-9.0, -3.0));
      const double phi = uniform(0.0, 6.283185307179586);
      const vec3 m = std::cos(phi) * b.n1 + std::sin(phi) * b.n2;
      double a, y, solid;
      if (coin()) {
        // side point P = (x, r(x)), outward normal (-sin a, cos a)
        const double x = uniform(0.0, L);
        const double d = radius + gap;
        a = x - d * sin_a;
        y = r2 + x * slope + d * cos_a;
        if (y < 0.0) continue;  // crossed the axis: not the meridian point assumed
        double frustum;
        if (d >= 0.0) {
          frustum = d;
        } else {
          if (a < 0.0 || a > L) continue;
          frustum = std::max({-a, a - L, d});  // inside a convex polygon: exact
        }
        solid = std::min(frustum, ball_distances(a, y));
      } else {
        // point of a ball in a random direction of the meridian half-plane
        const bool distal = coin();
        const double ball_r = distal ? r2 : r1;
        const double reach = ball_r + radius + gap;
        if (reach < 0.0) continue;
        const double beta = uniform(0.0, 3.141592653589793);
        a = (distal ? 0.0 : L) + reach * std::cos(beta);
        y = reach * std::sin(beta);
        const double balls = ball_distances(a, y);
        if (frustum_lower_bound(a, y) < balls) continue;  // the frustum might be nearer
        solid = balls;
      }
      const double signed_gap = solid - radius;
      if (!(std::fabs(signed_gap) >= 1e-9 && std::fabs(signed_gap) <= 1e-3)) continue;
      c.sphere.center = e + a * b.u + y * m;
      c.expected_gap = signed_gap;
      return;
    }
    // fallback, always valid: straight beyond the tip, nearest the ball at E
    const double gap = 1e-6;
    c.sphere.center = e - (r2 + radius + gap) * b.u;
    c.expected_gap = std::min(gap, L + r2 + gap - r1);
  }

  std::mt19937_64 rng_;
  std::uint64_t count_ = 0;
};

// n cases of the mix from one seed.
inline std::vector<Case> make_cases(std::size_t n, std::uint64_t seed) {
  CaseGenerator generator(seed);
  std::vector<Case> cases;
  cases.reserve(n);
  for (std::size_t i = 0; i < n; ++i) cases.push_back(generator.next());
  return cases;
}

// One line naming a case, for failure messages.
inline std::string describe(const Case& c) {
  auto v = [](const vec3& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p.x, p.y, p.z);
    return std::string(buf);
  };
  char buf[128];
  std::snprintf(buf, sizeof buf, "case #%llu family=%s r1=%.17g r2=%.17g R=%.17g",
                static_cast<unsigned long long>(c.index), family_name(c.family),
                c.segment.proximal_radius, c.segment.distal_radius, c.sphere.radius);
  return std::string(buf) + " D=" + v(c.segment.proximal) + " E=" + v(c.segment.distal) +
         " O=" + v(c.sphere.center);
}

}  // namespace frusta::scenes
