// SPDX-License-Identifier: MIT
#include "bake/baker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "spheretree/tree_builder.h"
#include "spheretree/tree_limits.h"

namespace frusta {

BakeError measure_bake_error(const MeshQueries& queries, const TriangleMesh& mesh,
                             const SphereTree& tree, int64_t samples, uint64_t seed,
                             const ProgressFn& progress) {
  BakeError error;
  // each half of the measurement reports every 1024 points
  const auto stop = [&](int64_t done, double half) {
    return progress && (done & 1023) == 0 &&
           !progress(0.5 * half + 0.5 * static_cast<double>(done) / static_cast<double>(samples));
  };
  // (a) how far a finger sinks before it touches: surface points outside every leaf
  int64_t surface_points = 0;
  for (const SurfaceSample& s : sample_surface(mesh, static_cast<size_t>(samples), seed)) {
    error.uncovered = std::max(error.uncovered, distance_to_leaves(tree, s.point));
    if (stop(++surface_points, 0.0)) {
      error.cancelled = true;
      return error;
    }
  }

  // (b) how far above the surface a finger stops: leaf points outside the mesh.
  // Points are spread over the leaves by area, at least 4 on each.
  double total_area = 0.0;
  for (const Sphere& l : tree.leaves) total_area += l.radius * l.radius;
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  std::normal_distribution<double> gauss;
  int64_t leaf_points = 0;
  for (const Sphere& l : tree.leaves) {
    const double share = total_area > 0.0 ? l.radius * l.radius / total_area : 0.0;
    const int64_t n = std::max<int64_t>(4, static_cast<int64_t>(std::ceil(share * static_cast<double>(samples))));
    for (int64_t k = 0; k < n; ++k) {
      // braces: the three draws in order on every compiler (function arguments have none)
      const vec3 q = l.center + l.radius * glm::normalize(vec3{gauss(rng), gauss(rng), gauss(rng)});
      if (stop(std::min(++leaf_points, samples), 1.0)) {
        error.cancelled = true;
        return error;
      }
      // inside another leaf: not on the union's boundary, cannot stand out further
      if (distance_to_leaves(tree, q) < -1e-12) continue;
      if (queries.inside(q)) continue;
      error.protruding = std::max(error.protruding, queries.closest(q).distance);
    }
  }
  error.samples = std::min(samples, leaf_points);
  return error;
}

frusta_result bake_sphere_tree(const TriangleMesh& mesh, const BakeParams& params,
                               const ProgressFn& progress, TreeFile* out, bool* target_met) {
  // the C++ callers' boundary (the sample generator, tests, benchmarks); the C ABI
  // and frusta-bake have refused a bad value already, with their own wording
  if (frusta_result r = check_bake_params(params)) return r;
  if (frusta_result r = check_mesh(mesh, "mesh")) return r;

  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<MeshQueries> queries;
  if (frusta_result r = MeshQueries::create(mesh, &queries)) return r;
  // how much each attempt that did not fit the budget coarsens the target: at least a
  // quarter (an attempt that ran out filling the interior says nothing finer), at most
  // fourfold (a cover's count falls faster than the square of its error once its balls
  // reach their largest)
  constexpr double kCoarsenLeast = 1.25, kCoarsenMost = 4.0;
  constexpr int kBudgetHalvings = 3;
  constexpr double kSamplesPerLeaf = 64.0;
  // the cover takes most of a bake, the error's measurement the rest
  constexpr double kCoverShare = 0.7;
  const auto share = [&progress](double from, double width) {
    return progress ? ProgressFn([&progress, from, width](double f) { return progress(from + width * f); })
                    : ProgressFn();
  };
  // A budget the target does not fit in coarsens the target until the cover fits, so the
  // tree covers the whole object at the finest error the budget allows: a cover stopped
  // by its budget had covered a corner of the object at the target and left the rest
  // bare (a mug in 300 leaves: 129 mm uncovered). Each attempt aims at the error the last
  // one's progress says fits (its leaves cover a share of the surface about as the
  // square of the error); then, while a fitting cover leaves a fifth of the budget
  // unused, a few halvings between it and the finest that did not fit. Each attempt
  // takes half what is left of the cover's progress.
  CoverResult cover;
  double aimed = params.target_error, progress_from = 0.0;
  auto attempt = [&](double aim) {
    // first on samples enough for the budget's leaves (kSamplesPerLeaf each): a budget
    // that runs out on them runs out on the target's density too, which the mug in 300
    // leaves had sampled at 0.1 mm for 5 s to find; only a cover that fits is made again
    // at the target's density
    const double progress_width = 0.5 * (kCoverShare - progress_from);
    const double sparse = kSamplesPerLeaf * static_cast<double>(params.max_leaves);
    CoverResult c = cover_with_spheres(mesh, *queries, {aim, params.max_leaves, params.seed, sparse},
                                       share(progress_from, 0.5 * progress_width));
    if (!c.cancelled && !c.budget_exhausted && c.sparse)
      c = cover_with_spheres(mesh, *queries, {aim, params.max_leaves, params.seed},
                             share(progress_from + 0.5 * progress_width, 0.5 * progress_width));
    progress_from += progress_width;
    return c;
  };
  double too_fine = 0.0;  // the coarsest aim that did not fit (0: none)
  for (;;) {
    cover = attempt(aimed);
    if (cover.cancelled) return fail(FRUSTA_ERROR_CANCELLED, "the bake was cancelled");
    if (!cover.budget_exhausted || aimed >= kMaxTargetError) break;
    too_fine = aimed;
    aimed = std::min(kMaxTargetError, aimed * std::clamp(1.1 / std::sqrt(std::max(cover.reached, 1e-6)),
                                                         kCoarsenLeast, kCoarsenMost));
  }
  for (int halving = 0; halving < kBudgetHalvings && too_fine > 0.0 && !cover.budget_exhausted &&
                        static_cast<double>(cover.leaves.size()) < 0.8 * static_cast<double>(params.max_leaves);
       ++halving) {
    const double between = std::sqrt(too_fine * aimed);
    CoverResult finer = attempt(between);
    if (finer.cancelled) return fail(FRUSTA_ERROR_CANCELLED, "the bake was cancelled");
    if (finer.budget_exhausted) {
      too_fine = between;
    } else {
      aimed = between;
      cover = std::move(finer);
    }
  }
  if (cover.leaves.empty())
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "the mesh encloses no volume the baker could fill");

  TreeFile file;
  const TreeBuildOptions build{static_cast<int32_t>(params.branching)};
  if (frusta_result r = build_sphere_tree(cover.leaves, build, &file.tree)) return r;
  if (file.tree.depth > params.max_depth)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "max_depth is %lld but the %zu leaves need depth %d with branching %d: raise "
                "max_depth or branching", static_cast<long long>(params.max_depth),
                cover.leaves.size(), file.tree.depth, static_cast<int>(params.branching));
  file.bounds_min = vec3(INFINITY);
  file.bounds_max = vec3(-INFINITY);
  for (const Sphere& l : file.tree.leaves) {
    file.bounds_min = glm::min(file.bounds_min, l.center - l.radius);
    file.bounds_max = glm::max(file.bounds_max, l.center + l.radius);
  }
  // measured on samples the cover never saw
  const BakeError error = measure_bake_error(*queries, mesh, file.tree, params.error_samples,
                                             params.seed + 0x5eed, share(kCoverShare, 1.0 - kCoverShare));
  if (error.cancelled) return fail(FRUSTA_ERROR_CANCELLED, "the bake was cancelled");
  BakeRecord& b = file.bake;
  b.target_error = params.target_error;
  b.max_leaves = params.max_leaves;
  b.max_depth = static_cast<int32_t>(params.max_depth);
  b.triangle_count = static_cast<int32_t>(std::min<size_t>(mesh.triangles.size(), INT32_MAX));
  b.uncovered_error = error.uncovered;
  b.protruding_error = error.protruding;
  b.error_samples = error.samples;
  b.bake_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress) progress(1.0);
  *target_met = !cover.budget_exhausted && error.uncovered <= params.target_error &&
                error.protruding <= params.target_error;
  *out = std::move(file);
  return FRUSTA_OK;
}

}  // namespace frusta
