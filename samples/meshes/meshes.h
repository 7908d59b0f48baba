// SPDX-License-Identifier: MIT
// The sample objects' shapes, made procedurally: closed, outward-wound triangle meshes
// in metres. The sample generator writes them as glTF; the tests and the benchmarks
// bake them too.
#pragma once

#include <utility>
#include <vector>

#include "bake/triangle_mesh.h"

namespace frusta::scenes {

// The sample marble's radius: it fits between the thumb and index pads of the pinch
// scenarios (ball_pinch), opened 1.85 cm apart.
constexpr double kMarbleRadius = 0.0087;

// UV sphere; `rings` controls the triangle count (about 2 * rings^2).
TriangleMesh make_sphere(double radius, int rings);
// Axis-aligned box centred at the origin; each face split into n x n quads.
TriangleMesh make_box(const vec3& size, int n = 1);
// A bowl: a hemispherical shell (outer radius, wall thickness) with a rim, open side up.
TriangleMesh make_bowl(double radius, double thickness, int rings);
// A mug: a cylindrical cup (closed bottom) with a torus handle overlapping its wall.
TriangleMesh make_mug(double radius, double height, double wall, int segments);
// An octahedron: sharp convex edges and vertices.
TriangleMesh make_octahedron(double radius);
// A straight prism: a convex polygon (x, z) in the x-z plane, either winding, extruded
// `length` along y and centred on y = 0. Its side edges are as sharp as the polygon's
// corners.
TriangleMesh make_prism(const std::vector<std::pair<double, double>>& section, double length);

// Append b to a (no welding): overlapping parts make a non-manifold union, as in
// real assets.
void append(TriangleMesh& a, const TriangleMesh& b);

}  // namespace frusta::scenes
