// SPDX-License-Identifier: MIT
#include "bake/triangle_mesh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "meshes/meshes.h"

namespace frusta {
namespace {

TEST(TriangleMesh, CheckNamesTheFault) {
  TriangleMesh m = scenes::make_box(vec3(0.1));
  EXPECT_EQ(check_mesh(m, "box"), FRUSTA_OK);
  m.vertices[3].y = std::nan("");
  EXPECT_EQ(check_mesh(m, "box"), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("box: vertex 3"), std::string::npos);
  m = scenes::make_box(vec3(0.1));
  m.triangles[5][1] = 999;
  EXPECT_EQ(check_mesh(m, "box"), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("triangle 5"), std::string::npos);
  m.triangles = {{0, 0, 1}};  // no area
  EXPECT_EQ(check_mesh(m, "box"), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta::last_error_message()).find("no triangles with area"), std::string::npos);
}

TEST(TriangleMesh, SamplesLieOnTheSurfaceWithOutwardNormals) {
  const TriangleMesh box = scenes::make_box(vec3(0.2, 0.1, 0.04), 3);
  EXPECT_NEAR(surface_area(box), 2 * (0.2 * 0.1 + 0.2 * 0.04 + 0.1 * 0.04), 1e-12);
  int top = 0;
  for (const SurfaceSample& s : sample_surface(box, 20000, 3)) {
    const vec3 a = glm::abs(s.point);
    const bool on_face = std::fabs(a.x - 0.1) < 1e-12 || std::fabs(a.y - 0.05) < 1e-12 ||
                         std::fabs(a.z - 0.02) < 1e-12;
    EXPECT_TRUE(on_face);
    EXPECT_GT(glm::dot(s.normal, s.point), 0.0);  // outward on a box centred at 0
    top += s.normal.z > 0.5;
  }
  // area-weighted: the top face holds 0.02 of 0.064 m^2
  EXPECT_NEAR(top / 20000.0, 0.02 / 0.064, 0.015);
}

}  // namespace
}  // namespace frusta
