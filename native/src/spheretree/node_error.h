// SPDX-License-Identifier: MIT
// How far each node's sphere stands out of the leaves beneath it: the level-of-detail
// error of letting the node stand in for them (a body stopped on the node's surface is
// at most that far from the nearest of its leaves).
#pragma once

#include <array>

#include "spheretree/sphere_tree.h"

namespace frusta {

// The directions on which a node's surface is sampled: a Fibonacci lattice, nearly
// even over the sphere and the same on every platform.
constexpr int kNodeErrorDirections = 64;
const std::array<vec3, kNodeErrorDirections>& node_error_directions();

// Fills tree.node_error bottom-up: a leaf's is 0; an inner node's is the largest, over
// kNodeErrorDirections points p of its surface, of min over its children of
// (distance from p to the child's sphere + the child's error), rounded up to a float.
// An estimate: between the sampled points the surface may stand out by up to the
// radius times the sampling's angular gap more. Needs children stored after their
// parent (the builder and the loader guarantee it); ~ 64 x branching distances per node.
// Fills tree.node_overhang too: for an inner node, how far the spheres of the inner
// nodes beneath it reach past its own, rounded up to a float.
void compute_node_errors(SphereTree& tree);

}  // namespace frusta
