// SPDX-License-Identifier: MIT
#include "bake/baker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include "bake/sphere_cover.h"
#include "core/error.h"
#include "meshes/meshes.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

struct Case {
  const char* name;
  TriangleMesh mesh;
};

std::vector<Case> objects() {
  return {{"sphere", scenes::make_sphere(0.04, 48)},
          {"box", scenes::make_box(vec3(0.10, 0.06, 0.04), 4)},
          {"plate", scenes::make_box(vec3(0.12, 0.08, 0.004), 2)},
          {"octahedron", scenes::make_octahedron(0.05)},
          {"bowl", scenes::make_bowl(0.06, 0.006, 24)},
          {"mug", scenes::make_mug(0.04, 0.09, 0.006, 48)}};
}

// The test's own error check: fresh samples, brute force over every leaf, Embree
// for inside/outside and distances; none of the baker's measuring code.
void independent_errors(const TriangleMesh& mesh, const SphereTree& tree, double* uncovered,
                        double* protruding) {
  std::unique_ptr<MeshQueries> q;
  ASSERT_EQ(MeshQueries::create(mesh, &q), FRUSTA_OK);
  *uncovered = 0.0;
  for (const SurfaceSample& s : sample_surface(mesh, 20000, 777)) {
    double gap = INFINITY;
    for (const Sphere& l : tree.leaves) gap = std::min(gap, glm::length(s.point - l.center) - l.radius);
    *uncovered = std::max(*uncovered, gap);
  }
  *protruding = 0.0;
  std::mt19937_64 rng(778);
  std::normal_distribution<double> g;
  for (const Sphere& l : tree.leaves)
    for (int k = 0; k < 6; ++k) {
      const vec3 p = l.center + l.radius * glm::normalize(vec3(g(rng), g(rng), g(rng)));
      if (!q->inside(p)) *protruding = std::max(*protruding, q->closest(p).distance);
    }
}

TEST(Baker, BothErrorFiguresMeetTheTargetAndAnIndependentCheckAgrees) {
  std::uint64_t index = 0;
  for (Case& c : objects()) {
    if (!scenes::scenario_runs(index++)) continue;
    BakeParams params;
    params.target_error = 0.001;
    params.error_samples = 100000;
    TreeFile file;
    bool met = false;
    ASSERT_EQ(bake_sphere_tree(c.mesh, params, nullptr, &file, &met), FRUSTA_OK)
        << c.name << ": " << frusta::last_error_message();
    EXPECT_TRUE(met) << c.name;
    EXPECT_LE(file.bake.uncovered_error, 0.001) << c.name;
    EXPECT_LE(file.bake.protruding_error, 0.001) << c.name;
    EXPECT_GE(file.bake.error_samples, 100000) << c.name;
    double uncovered, protruding;
    independent_errors(c.mesh, file.tree, &uncovered, &protruding);
    EXPECT_LE(uncovered, 0.001) << c.name;
    EXPECT_LE(protruding, 0.001) << c.name;
    std::printf("%-10s %6zu triangles %6zu leaves depth %2d  uncovered %.3f mm  protruding %.3f mm"
                "  (independent %.3f / %.3f)  %.2f s\n",
                c.name, c.mesh.triangles.size(), file.tree.leaves.size(), file.tree.depth,
                file.bake.uncovered_error * 1e3, file.bake.protruding_error * 1e3, uncovered * 1e3,
                protruding * 1e3, file.bake.bake_seconds);
  }
}

TEST(Baker, TheInteriorIsFilledSoADeepFingerMeetsLeaves) {
  const TriangleMesh box = scenes::make_box(vec3(0.2, 0.2, 0.2), 2);
  BakeParams params;
  params.target_error = 0.002;
  TreeFile file;
  bool met = false;
  ASSERT_EQ(bake_sphere_tree(box, params, nullptr, &file, &met), FRUSTA_OK);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-0.09, 0.09);
  for (int i = 0; i < 2000; ++i) {
    const vec3 p(u(rng), u(rng), u(rng));
    // every interior point lies within one grid step of a leaf
    EXPECT_LT(distance_to_leaves(file.tree, p), 0.2 / 48.0) << p.x << " " << p.y << " " << p.z;
  }
}

// A budget the target does not fit in coarsens the target until the cover fits: the
// tree covers the whole object within the budget, at the error its figures report (and
// meets the target where they say so). Before, the cover stopped where the budget ran
// out, a corner of the object covered at the target and the rest bare.
TEST(Baker, ALeafBudgetTheTargetDoesNotFitCoarsensTheWholeCover) {
  BakeParams params;
  params.target_error = 0.001;
  const TriangleMesh sphere = scenes::make_sphere(0.04, 32);
  TreeFile whole;
  bool met = false;
  ASSERT_EQ(bake_sphere_tree(sphere, params, nullptr, &whole, &met), FRUSTA_OK);
  ASSERT_TRUE(met);
  const int64_t leaves = static_cast<int64_t>(whole.tree.leaves.size());
  for (int64_t budget : {int64_t{1}, int64_t{8}, leaves / 8, leaves / 2}) {
    params.max_leaves = budget;
    TreeFile file;
    ASSERT_EQ(bake_sphere_tree(sphere, params, nullptr, &file, &met), FRUSTA_OK);
    EXPECT_LE(file.tree.leaves.size(), static_cast<size_t>(budget));
    EXPECT_GE(file.tree.leaves.size(), static_cast<size_t>((budget + 1) / 2)) << "half the budget unused";
    // the figures say how far from the target, and whether it was met
    EXPECT_EQ(met, std::max(file.bake.uncovered_error, file.bake.protruding_error) <= params.target_error)
        << budget;
    if (budget <= leaves / 8) {
      EXPECT_FALSE(met) << budget;
    }
    // the whole sphere covered: none of it further from a leaf than half its radius (a
    // cover stopped by the budget left most of it bare, a diameter from the nearest leaf)
    EXPECT_LT(file.bake.uncovered_error, 0.02) << budget << " leaves";
  }
}

// The baker first tries a target on samples enough for the budget's leaves and coarsens
// it at once when they exhaust the budget; that stands on this: a budget that runs out
// on sparser samples runs out on the target's density too (a cover of fewer samples needs
// no more leaves), and one that fits the sparse samples is flagged as no cover of the
// target.
TEST(Baker, ABudgetThatRunsOutOnSparseSamplesRunsOutOnDenseOnes) {
  for (Case& c : objects()) {
    std::unique_ptr<MeshQueries> q;
    ASSERT_EQ(MeshQueries::create(c.mesh, &q), FRUSTA_OK);
    for (double target : {0.003, 0.0015})
      for (int64_t budget : {20, 100}) {
        const CoverResult sparse = cover_with_spheres(c.mesh, *q, {target, budget, 1, 2e4}, nullptr);
        const CoverResult dense = cover_with_spheres(c.mesh, *q, {target, budget, 1}, nullptr);
        SCOPED_TRACE(::testing::Message() << c.name << ", " << target << " m, " << budget << " leaves");
        EXPECT_EQ(sparse.surface_samples, 20000u);
        EXPECT_EQ(sparse.sparse, dense.surface_samples > 20000u);
        EXPECT_FALSE(dense.sparse);
        if (sparse.budget_exhausted) {
          EXPECT_TRUE(dense.budget_exhausted);
        }
      }
  }
}

TEST(Baker, BadParametersAndMeshesAreRefused) {
  TreeFile file;
  bool met;
  BakeParams p;
  p.target_error = 0.0;
  EXPECT_EQ(bake_sphere_tree(scenes::make_box(vec3(0.1)), p, nullptr, &file, &met), FRUSTA_ERROR_OUT_OF_RANGE);
  p = BakeParams{};
  p.branching = 1;
  EXPECT_EQ(bake_sphere_tree(scenes::make_box(vec3(0.1)), p, nullptr, &file, &met), FRUSTA_ERROR_OUT_OF_RANGE);
  TriangleMesh empty;
  EXPECT_EQ(bake_sphere_tree(empty, BakeParams{}, nullptr, &file, &met), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("no triangles"), std::string::npos);
}

}  // namespace
}  // namespace frusta
