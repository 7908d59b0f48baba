// SPDX-License-Identifier: MIT
#include "bake/mesh_queries.h"

#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "meshes/meshes.h"

namespace frusta {
namespace {

// Property: on a sphere mesh, Embree's closest point and the vote agree with the
// analytic sphere within the tessellation's sag.
TEST(MeshQueries, AgreeWithTheAnalyticSphere) {
  const double radius = 0.05;
  const int rings = 64;
  const TriangleMesh mesh = scenes::make_sphere(radius, rings);
  std::unique_ptr<MeshQueries> q;
  ASSERT_EQ(MeshQueries::create(mesh, &q), FRUSTA_OK);
  // chord sag of the tessellation: r (1 - cos(pi / rings)), plus float vertices
  const double sag = radius * (1.0 - std::cos(3.14159265358979 / rings)) + 1e-7;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const vec3 p(u(rng), u(rng), u(rng));
    const double exact = glm::length(p) - radius;
    const MeshQueries::Closest c = q->closest(p);
    EXPECT_NEAR(c.distance, std::fabs(exact), sag) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(glm::length(c.point - p), c.distance, 1e-12);
    if (std::fabs(exact) > sag) {
      EXPECT_EQ(q->inside(p), exact < 0.0);
      EXPECT_EQ(q->signed_distance(p) < 0.0, exact < 0.0);
    }
    inside += exact < 0.0;
  }
  EXPECT_GT(inside, 500);
}

TEST(MeshQueries, VotingSurvivesAHoleInTheMesh) {
  TriangleMesh box = scenes::make_box(vec3(0.1), 4);
  box.triangles.erase(box.triangles.begin(), box.triangles.begin() + 8);  // open a quarter face
  std::unique_ptr<MeshQueries> q;
  ASSERT_EQ(MeshQueries::create(box, &q), FRUSTA_OK);
  EXPECT_TRUE(q->inside(vec3(0.0)));
  EXPECT_TRUE(q->inside(vec3(0.02, -0.03, 0.01)));
  EXPECT_FALSE(q->inside(vec3(0.2, 0.0, 0.0)));
  EXPECT_FALSE(q->inside(vec3(-0.06, 0.0, 0.0)));
}

}  // namespace
}  // namespace frusta
