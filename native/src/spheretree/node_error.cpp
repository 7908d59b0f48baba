// SPDX-License-Identifier: MIT
#include "spheretree/node_error.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {
namespace {

std::array<vec3, kNodeErrorDirections> lattice() {
  std::array<vec3, kNodeErrorDirections> d;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kNodeErrorDirections; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / kNodeErrorDirections;
    const double ring = std::sqrt(1.0 - z * z), phi = golden * i;
    d[static_cast<size_t>(i)] = vec3(ring * std::cos(phi), ring * std::sin(phi), z);
  }
  return d;
}

}  // namespace

const std::array<vec3, kNodeErrorDirections>& node_error_directions() {
  static const std::array<vec3, kNodeErrorDirections> directions = lattice();
  return directions;
}

namespace {

float round_up(double value) {
  float f = static_cast<float>(value);
  while (static_cast<double>(f) < value) f = std::nextafter(f, INFINITY);
  return f;
}

}  // namespace

void compute_node_errors(SphereTree& tree) {
  const std::array<vec3, kNodeErrorDirections>& directions = node_error_directions();
  tree.node_error.assign(tree.nodes.size(), 0.0f);
  tree.node_overhang.assign(tree.nodes.size(), 0.0f);
  // per direction, its sample point and its gap so far: laid out for the vector units
  alignas(32) double px[kNodeErrorDirections], py[kNodeErrorDirections], pz[kNodeErrorDirections];
  alignas(32) double nearest[kNodeErrorDirections];
  // children follow their parent, so walking backwards meets every child first
  for (size_t i = tree.nodes.size(); i-- > 0;) {
    const TreeNode& n = tree.nodes[i];
    if (n.count == 0) continue;
    const Sphere bound = tree.node_sphere(static_cast<int32_t>(i));
    for (int k = 0; k < kNodeErrorDirections; ++k) {
      const vec3 p = bound.center + bound.radius * directions[static_cast<size_t>(k)];
      px[k] = p.x;
      py[k] = p.y;
      pz[k] = p.z;
      nearest[k] = INFINITY;
    }
    for (int32_t c = 0; c < n.count; ++c) {
      const size_t child = static_cast<size_t>(n.first + c);
      const TreeNode& cn = tree.nodes[child];
      const Sphere s = cn.count == 0 ? tree.leaves[static_cast<size_t>(cn.first)]
                                     : tree.node_sphere(static_cast<int32_t>(child));
      const double cx = s.center.x, cy = s.center.y, cz = s.center.z, r = s.radius;
      const double e = tree.node_error[child];
      for (int k = 0; k < kNodeErrorDirections; ++k) {
        const double dx = px[k] - cx, dy = py[k] - cy, dz = pz[k] - cz;
        const double gap = std::max(0.0, std::sqrt(dx * dx + dy * dy + dz * dz) - r) + e;
        nearest[k] = std::min(nearest[k], gap);
      }
    }
    double worst = 0.0;
    for (int k = 0; k < kNodeErrorDirections; ++k) worst = std::max(worst, nearest[k]);
    tree.node_error[i] = round_up(worst);
    double overhang = 0.0;  // the inner children's spheres, and what sticks out of them
    for (int32_t c = 0; c < n.count; ++c) {
      const int32_t child = n.first + c;
      if (tree.nodes[static_cast<size_t>(child)].count == 0) continue;  // a leaf lies inside
      const Sphere s = tree.node_sphere(child);
      overhang = std::max(overhang, glm::length(s.center - bound.center) + s.radius +
                                        tree.node_overhang[static_cast<size_t>(child)] - bound.radius);
    }
    tree.node_overhang[i] = round_up(overhang);
  }
}

}  // namespace frusta
