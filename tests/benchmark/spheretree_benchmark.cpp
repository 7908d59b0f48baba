// SPDX-License-Identifier: MIT
// tools/bench spheretree: the bake's time against its error, and tree queries
// against a brute-force scan of every leaf, in one run so the ratios hold.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "bake/baker.h"
#include "core/error.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "meshes/meshes.h"
#include "spheretree/node_error.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

void report_bake(benchmark::State& state, const TriangleMesh& mesh, double target) {
  BakeParams params;
  params.target_error = target;
  TreeFile file;
  bool met = false;
  for (auto _ : state) {
    if (bake_sphere_tree(mesh, params, nullptr, &file, &met) != FRUSTA_OK) {
      state.SkipWithError(frusta::last_error_message());
      return;
    }
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["target_error_mm"] = target * 1e3;
  state.counters["leaves"] = static_cast<double>(file.tree.leaves.size());
  state.counters["depth"] = file.tree.depth;
  state.counters["bake_seconds"] = file.bake.bake_seconds;
  state.counters["uncovered_error_mm"] = file.bake.uncovered_error * 1e3;
  state.counters["protruding_error_mm"] = file.bake.protruding_error * 1e3;
  state.counters["target_met"] = met;
}

// bake time and error against triangle count: a 4 cm ball tessellated ever finer
void BM_BakeByTriangles(benchmark::State& state) {
  const int rings = static_cast<int>(state.range(0));
  report_bake(state, scenes::make_sphere(0.04, rings), 0.001);
}
BENCHMARK(BM_BakeByTriangles)->Arg(16)->Arg(50)->Arg(158)->Arg(500)->Iterations(1)->Unit(benchmark::kMillisecond);

// bake time and error against the target: a mug (flat, curved, concave, a handle)
void BM_BakeByTargetError(benchmark::State& state) {
  report_bake(state, scenes::make_mug(0.04, 0.09, 0.006, 48), static_cast<double>(state.range(0)) * 1e-4);
}
BENCHMARK(BM_BakeByTargetError)->Arg(40)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kMillisecond);

// The baseline the surface-fitted cover must beat: an octree-style grid of cubes of
// side h over the surface, each leaf the cube's circumscribed sphere, h the largest
// that keeps both error figures within the target. Same mesh, same error measure.
void BM_GridBaselineByTargetError(benchmark::State& state) {
  const TriangleMesh mesh = scenes::make_mug(0.04, 0.09, 0.006, 48);
  const double target = static_cast<double>(state.range(0)) * 1e-4;
  std::unique_ptr<MeshQueries> queries;
  MeshQueries::create(mesh, &queries);
  // a cell's circumscribed sphere can stand out of the surface by up to its radius:
  // take h so that the radius equals the target
  const double h = target / (0.5 * std::sqrt(3.0));
  const std::vector<SurfaceSample> samples =
      sample_surface(mesh, static_cast<size_t>(std::max(1e5, 16.0 * surface_area(mesh) / (h * h))), 3);
  SphereTree tree;
  for (auto _ : state) {
    std::vector<glm::i64vec3> cells;
    for (const SurfaceSample& s : samples)
      cells.emplace_back(std::floor(s.point.x / h), std::floor(s.point.y / h), std::floor(s.point.z / h));
    std::sort(cells.begin(), cells.end(), [](auto a, auto b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    std::vector<Sphere> leaves;
    for (const auto& c : cells) leaves.push_back({(vec3(c) + 0.5) * h, 0.5 * std::sqrt(3.0) * h});
    build_sphere_tree(leaves, {4}, &tree);
  }
  const BakeError error = measure_bake_error(*queries, mesh, tree, 100000, 11);
  state.counters["target_error_mm"] = target * 1e3;
  state.counters["leaves"] = static_cast<double>(tree.leaves.size());
  state.counters["uncovered_error_mm"] = error.uncovered * 1e3;
  state.counters["protruding_error_mm"] = error.protruding * 1e3;
}
BENCHMARK(BM_GridBaselineByTargetError)->Arg(40)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kMillisecond);

// A surface-like object of N leaves: spheres on a 5 cm shell, sized to overlap.
std::vector<Sphere> shell_leaves(int leaves) {
  std::mt19937_64 rng(leaves);
  std::normal_distribution<double> g;
  const double radius = 0.05, leaf = 2.0 * radius * std::sqrt(4.0 / leaves);
  std::vector<Sphere> spheres;
  for (int i = 0; i < leaves; ++i)
    spheres.push_back({(radius - leaf) * glm::normalize(vec3(g(rng), g(rng), g(rng))), leaf});
  return spheres;
}

SphereTree shell_tree(int leaves) {
  SphereTree tree;
  build_sphere_tree(shell_leaves(leaves), {4}, &tree);
  return tree;
}

// a fingertip pressed 2 mm into the shell from many directions
std::vector<SegmentFrame> fingertips(int count) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  std::vector<SegmentFrame> frames;
  for (int i = 0; i < count; ++i) {
    const vec3 n = glm::normalize(vec3(g(rng), g(rng), g(rng)));
    const vec3 tip = (0.05 + 0.008 - 0.002) * n;
    frames.push_back(make_segment_frame({tip + 0.025 * n, tip, 0.009, 0.008}));
  }
  return frames;
}

void BM_TreeQuerySegment(benchmark::State& state) {
  const SphereTree tree = shell_tree(static_cast<int>(state.range(0)));
  const std::vector<SegmentFrame> frames = fingertips(256);
  std::vector<TreeHit> hits(1 << 16);
  size_t i = 0;
  int64_t found = 0, visited = 0;
  for (auto _ : state) {
    const TreeQueryStats s = query_segment(tree, frames[i++ & 255], 0.002, -1, hits.data(),
                                           static_cast<int32_t>(hits.size()));
    found += s.hits;
    visited += s.visited;
  }
  state.counters["leaves"] = static_cast<double>(tree.leaves.size());
  state.counters["hits_per_query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
  state.counters["nodes_visited"] = static_cast<double>(visited) / static_cast<double>(state.iterations());
  state.counters["bytes_per_leaf"] =
      static_cast<double>(tree.nodes.size() * (sizeof(TreeNode) + sizeof(float)) +
                          tree.leaves.size() * sizeof(Sphere)) /
      static_cast<double>(tree.leaves.size());
}
BENCHMARK(BM_TreeQuerySegment)->RangeMultiplier(10)->Range(100, 1000000)->Unit(benchmark::kMicrosecond);

// The same queries testing what they report in single precision only (the solver's
// detection, which bounds every hit's gap anyway): its time against its error, the hits
// it keeps beyond query_segment's (`extra_hits_per_query`) and how far beyond the margin
// the farthest of them lies (`farthest_beyond_m`, by exact_distance).
void BM_TreeQuerySegmentLoose(benchmark::State& state) {
  const SphereTree tree = shell_tree(static_cast<int>(state.range(0)));
  const std::vector<SegmentFrame> frames = fingertips(256);
  std::vector<TreeHit> hits(1 << 16);
  int64_t extra = 0;
  double farthest = 0.0;
  for (const SegmentFrame& frame : frames) {
    const int32_t capacity = static_cast<int32_t>(hits.size());
    const int32_t loose = query_segment_loose(tree, frame, 0.002, -1, hits.data(), capacity).hits;
    for (int32_t k = 0; k < loose; ++k) {
      const double beyond =
          exact_distance(frame,
                         tree.leaves[static_cast<size_t>(hits[static_cast<size_t>(k)].leaf)]) -
          0.002;
      farthest = std::max(farthest, beyond);
    }
    extra += loose - query_segment(tree, frame, 0.002, -1, hits.data(), capacity).hits;
  }
  size_t i = 0;
  int64_t found = 0;
  for (auto _ : state) {
    found += query_segment_loose(tree, frames[i++ & 255], 0.002, -1, hits.data(),
                                 static_cast<int32_t>(hits.size()))
                 .hits;
  }
  state.counters["leaves"] = static_cast<double>(tree.leaves.size());
  state.counters["hits_per_query"] =
      static_cast<double>(found) / static_cast<double>(state.iterations());
  state.counters["extra_hits_per_query"] =
      static_cast<double>(extra) / static_cast<double>(frames.size());
  state.counters["farthest_beyond_m"] = farthest;
}
BENCHMARK(BM_TreeQuerySegmentLoose)
    ->RangeMultiplier(10)
    ->Range(100, 1000000)
    ->Unit(benchmark::kMicrosecond);

// The same queries walking with may_touch in double at every node, one at a time (the
// walk before query_segment culled children four at a time in single precision): the
// ratio of the two is what that saves, and `queries_differing` (0) its error: the hits
// of each query compared, node for node.
void BM_TreeQuerySegmentExactWalk(benchmark::State& state) {
  const SphereTree tree = shell_tree(static_cast<int>(state.range(0)));
  const std::vector<SegmentFrame> frames = fingertips(256);
  std::vector<TreeHit> hits(1 << 16), culled(1 << 16);
  int64_t differing = 0;
  for (size_t q = 0; q < frames.size(); ++q) {
    int32_t count = 0;
    walk_tree(tree, [&](const Sphere& s) { return may_touch(frames[q], s, 0.002); }, TreeCut(),
              [&](const TreeHit& h) { hits[static_cast<size_t>(count++)] = h; });
    const TreeQueryStats s =
        query_segment(tree, frames[q], 0.002, -1, culled.data(), static_cast<int32_t>(culled.size()));
    bool same = s.hits == count;
    for (int32_t k = 0; same && k < count; ++k)
      same = hits[static_cast<size_t>(k)].node == culled[static_cast<size_t>(k)].node;
    differing += !same;
  }
  size_t i = 0;
  int64_t found = 0;
  for (auto _ : state) {
    int32_t count = 0;
    walk_tree(tree, [&](const Sphere& s) { return may_touch(frames[i & 255], s, 0.002); }, TreeCut(),
              [&](const TreeHit& h) { hits[static_cast<size_t>(count++)] = h; });
    ++i;
    found += count;
  }
  state.counters["leaves"] = static_cast<double>(tree.leaves.size());
  state.counters["hits_per_query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
  state.counters["queries_differing"] = static_cast<double>(differing);
}
BENCHMARK(BM_TreeQuerySegmentExactWalk)->RangeMultiplier(10)->Range(100, 1000000)->Unit(benchmark::kMicrosecond);

// Building a tree (the node errors included) against computing its node errors alone:
// what the level of detail's error figures add to every tree built or loaded.
void BM_TreeBuild(benchmark::State& state) {
  const std::vector<Sphere> spheres = shell_leaves(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    SphereTree tree;
    build_sphere_tree(spheres, {4}, &tree);
    benchmark::DoNotOptimize(tree.nodes.data());
  }
}
BENCHMARK(BM_TreeBuild)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

void BM_NodeErrors(benchmark::State& state) {
  SphereTree tree = shell_tree(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    compute_node_errors(tree);
    benchmark::DoNotOptimize(tree.node_error.data());
  }
}
BENCHMARK(BM_NodeErrors)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

// the same queries scanning every leaf: the tree's speed-up is the ratio of the two
void BM_BruteForceScanSegment(benchmark::State& state) {
  const SphereTree tree = shell_tree(static_cast<int>(state.range(0)));
  const std::vector<SegmentFrame> frames = fingertips(256);
  size_t i = 0;
  int64_t found = 0;
  for (auto _ : state) {
    const SegmentFrame& f = frames[i++ & 255];
    for (const Sphere& leaf : tree.leaves) found += may_touch(f, leaf, 0.002);
  }
  state.counters["leaves"] = static_cast<double>(tree.leaves.size());
  state.counters["hits_per_query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_BruteForceScanSegment)->RangeMultiplier(10)->Range(100, 1000000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace frusta
