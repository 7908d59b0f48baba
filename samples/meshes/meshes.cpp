// SPDX-License-Identifier: MIT
#include "meshes/meshes.h"

#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace frusta::scenes {

namespace {

constexpr double kPi = 3.14159265358979323846;

double signed_volume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles)
    v += glm::dot(m.vertices[t[0]], glm::cross(m.vertices[t[1]], m.vertices[t[2]])) / 6.0;
  return v;
}

// closed meshes are wound outwards: flip a mesh whose volume comes out negative
TriangleMesh outward(TriangleMesh m) {
  if (signed_volume(m) < 0.0)
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// Revolve a profile (radius, height) about z. The first and last points must lie on
// the axis (radius 0); they become single pole vertices.
TriangleMesh revolve(const std::vector<std::pair<double, double>>& profile, int segments) {
  TriangleMesh m;
  std::vector<std::vector<uint32_t>> rings;
  for (const auto& [r, z] : profile) {
    std::vector<uint32_t> ring;
    const int count = r == 0.0 ? 1 : segments;
    for (int k = 0; k < count; ++k) {
      const double a = 2.0 * kPi * k / segments;
      ring.push_back(static_cast<uint32_t>(m.vertices.size()));
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
    rings.push_back(ring);
  }
  for (size_t i = 0; i + 1 < rings.size(); ++i) {
    const auto& a = rings[i];
    const auto& b = rings[i + 1];
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      const uint32_t a0 = a[a.size() == 1 ? 0 : static_cast<size_t>(k)],
                     a1 = a[a.size() == 1 ? 0 : static_cast<size_t>(k1)];
      const uint32_t b0 = b[b.size() == 1 ? 0 : static_cast<size_t>(k)],
                     b1 = b[b.size() == 1 ? 0 : static_cast<size_t>(k1)];
      if (a0 != a1) m.triangles.push_back({a0, a1, b1});
      if (b0 != b1) m.triangles.push_back({a0, b1, b0});
    }
  }
  return outward(m);
}

std::vector<std::pair<double, double>> arc(double radius, double z0, double from, double to,
                                           int steps) {
  std::vector<std::pair<double, double>> points;
  for (int i = 0; i <= steps; ++i) {
    const double a = from + (to - from) * i / steps;
    points.emplace_back(std::fabs(radius * std::cos(a)) < 1e-15 ? 0.0 : radius * std::cos(a),
                        z0 + radius * std::sin(a));
  }
  return points;
}

}  // namespace

void append(TriangleMesh& a, const TriangleMesh& b) {
  const uint32_t offset = static_cast<uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

TriangleMesh make_sphere(double radius, int rings) {
  return revolve(arc(radius, 0.0, -kPi / 2, kPi / 2, rings), 2 * rings);
}

TriangleMesh make_box(const vec3& size, int n) {
  TriangleMesh m;
  const vec3 h = 0.5 * size;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const uint32_t base = static_cast<uint32_t>(m.vertices.size());
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          vec3 p(0.0);
          p[axis] = side * h[axis];
          p[u] = -h[u] + size[u] * i / n;
          p[v] = -h[v] + size[v] * j / n;
          m.vertices.push_back(p);
        }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const uint32_t a = base + static_cast<uint32_t>(i * (n + 1) + j), b = a + 1,
                         c = a + static_cast<uint32_t>(n + 1), d = c + 1;
          // u x v points along +axis: keep that winding on the + side, flip on the -
          if (side > 0) {
            m.triangles.push_back({a, c, d});
            m.triangles.push_back({a, d, b});
          } else {
            m.triangles.push_back({a, d, c});
            m.triangles.push_back({a, b, d});
          }
        }
    }
  return m;
}

TriangleMesh make_bowl(double radius, double thickness, int rings) {
  auto profile = arc(radius, 0.0, -kPi / 2, 0.0, rings);  // outer wall, bottom to rim
  auto inner = arc(radius - thickness, 0.0, 0.0, -kPi / 2, rings);  // inner wall, rim to bottom
  profile.insert(profile.end(), inner.begin(), inner.end());
  return revolve(profile, 4 * rings);
}

TriangleMesh make_mug(double radius, double height, double wall, int segments) {
  TriangleMesh cup = revolve({{0.0, 0.0}, {radius, 0.0}, {radius, height}, {radius - wall, height},
                              {radius - wall, wall}, {0.0, wall}},
                             segments);
  // the handle: a torus in the x-z plane whose tube is buried 2/3 into the wall
  // (a non-manifold union, as modellers make them)
  const double major = 0.3 * height, minor = 2.0 * wall / 3.0;
  TriangleMesh handle;
  const int ring = segments / 2, tube = 12;
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      const double a = 2 * kPi * i / ring, b = 2 * kPi * j / tube;
      const double r = major + minor * std::cos(b);
      handle.vertices.emplace_back(radius + major + r * std::cos(a), minor * std::sin(b),
                                   0.5 * height + r * std::sin(a));
    }
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      auto at = [&](int x, int y) {
        return static_cast<uint32_t>(((x + ring) % ring) * tube + (y + tube) % tube);
      };
      handle.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      handle.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  append(cup, outward(handle));
  return cup;
}

TriangleMesh make_octahedron(double radius) {
  TriangleMesh m;
  m.vertices = {{radius, 0, 0}, {-radius, 0, 0}, {0, radius, 0},
                {0, -radius, 0}, {0, 0, radius}, {0, 0, -radius}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return outward(m);
}

TriangleMesh make_prism(const std::vector<std::pair<double, double>>& section, double length) {
  TriangleMesh m;
  const uint32_t n = static_cast<uint32_t>(section.size());
  for (double y : {-0.5 * length, 0.5 * length})
    for (const auto& [x, z] : section) m.vertices.emplace_back(x, y, z);
  for (uint32_t i = 0; i < n; ++i) {  // the sides, a quad each
    const uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  for (uint32_t i = 1; i + 1 < n; ++i) {  // the two caps, fans (the polygon is convex)
    m.triangles.push_back({0, i + 1, i});
    m.triangles.push_back({n, n + i, n + i + 1});
  }
  return outward(m);
}

}  // namespace frusta::scenes
