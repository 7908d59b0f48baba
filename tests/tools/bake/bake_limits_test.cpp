// SPDX-License-Identifier: MIT
// Issue 16: every bake parameter has a range, checked once where it enters (the C
// ABI, before the baker library is loaded; frusta-bake's options); Embree is never
// handed a point it would abort on; the baker library's messages say their code once.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "bake/bake_params.h"
#include "bake/mesh_queries.h"
#include "frusta/frusta.h"
#include "scenes/cube_mesh.h"
#include "meshes/meshes.h"

namespace frusta {
namespace {

using frusta_test::kCubeIndices;
using frusta_test::kCubeVertices;

// the message names the code once, at its start
void expect_code_once(frusta_result code) {
  const std::string message = frusta_last_error();
  const std::string name = frusta_result_name(code);
  EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
  EXPECT_EQ(message.find("FRUSTA_", name.size()), std::string::npos) << message;
}

TEST(BakeLimits, TheCAbiRefusesEveryParameterOutsideItsRange) {
  struct Bad {
    const char* field;
    void (*edit)(frusta_bake_def*);
    frusta_result code;
  };
  const Bad cases[] = {
      // 1e38 and 1e300 passed the old "> 0" rule, then Embree aborted the process
      {"target_error", [](frusta_bake_def* d) { d->target_error = 1e38; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = 1e300; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = 1.0001; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = 9e-6; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = 1e-300; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = -1.0; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = NAN; }, FRUSTA_ERROR_NOT_FINITE},
      {"target_error", [](frusta_bake_def* d) { d->target_error = -INFINITY; },
       FRUSTA_ERROR_NOT_FINITE},
      {"max_leaves", [](frusta_bake_def* d) { d->max_leaves = 0; }, FRUSTA_ERROR_OUT_OF_RANGE},
      {"max_leaves", [](frusta_bake_def* d) { d->max_leaves = INT64_MAX; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"branching", [](frusta_bake_def* d) { d->branching = INT32_MIN; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"branching", [](frusta_bake_def* d) { d->branching = 17; }, FRUSTA_ERROR_OUT_OF_RANGE},
      {"max_depth", [](frusta_bake_def* d) { d->max_depth = 0; }, FRUSTA_ERROR_OUT_OF_RANGE},
      {"max_depth", [](frusta_bake_def* d) { d->max_depth = INT32_MAX; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"error_samples", [](frusta_bake_def* d) { d->error_samples = 999; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"error_samples", [](frusta_bake_def* d) { d->error_samples = 10000001; },
       FRUSTA_ERROR_OUT_OF_RANGE},
      {"error_samples", [](frusta_bake_def* d) { d->error_samples = INT64_MIN; },
       FRUSTA_ERROR_OUT_OF_RANGE},
  };
  for (const Bad& c : cases) {
    frusta_bake_def def = frusta_default_bake_def();
    c.edit(&def);
    const frusta_tree_id sentinel{77, 0, 5};
    frusta_tree_id tree = sentinel;
    EXPECT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, &tree), c.code)
        << c.field;
    EXPECT_NE(std::string(frusta_last_error()).find(c.field), std::string::npos)
        << frusta_last_error();
    expect_code_once(c.code);
    EXPECT_EQ(tree.index1, sentinel.index1);
  }
}

TEST(BakeLimits, TheEdgesOfTheRangesBake) {
  for (double target : {kMaxTargetError, 0.5}) {
    frusta_bake_def def = frusta_default_bake_def();
    def.target_error = target;
    def.error_samples = kMinErrorSamples;
    def.seed = std::numeric_limits<uint64_t>::max();
    frusta_tree_id tree{};
    ASSERT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, &tree),
              FRUSTA_OK)
        << target << ": " << frusta_last_error();
    frusta_sphere_tree_info info{};
    info.struct_size = sizeof info;
    ASSERT_EQ(frusta_sphere_tree_get_info(tree, &info), FRUSTA_OK);
    EXPECT_GE(info.leaf_count, 1);
    EXPECT_TRUE(std::isfinite(info.uncovered_error) && std::isfinite(info.protruding_error));
    EXPECT_EQ(frusta_destroy_sphere_tree(tree), FRUSTA_OK);
  }
}

// what the baker library says came back as "CODE: CODE: message"
TEST(BakeLimits, TheBakerLibrarysMessagesSayTheirCodeOnce) {
  frusta_bake_def def = frusta_default_bake_def();
  frusta_tree_id tree{};
  EXPECT_EQ(frusta_create_sphere_tree_from_mesh(nullptr, 8, kCubeIndices, 36, &def, &tree),
            FRUSTA_ERROR_NULL_POINTER);
  EXPECT_NE(std::string(frusta_last_error()).find("vertices"), std::string::npos)
      << frusta_last_error();
  expect_code_once(FRUSTA_ERROR_NULL_POINTER);
  const int32_t bad[] = {0, 1, 9};
  EXPECT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, bad, 3, &def, &tree),
            FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta_last_error()).find("indices[2] is 9"), std::string::npos);
  expect_code_once(FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST(BakeLimits, CheckBakeParamsSaysWhichField) {
  BakeParams p;
  BakeField field = BakeField::kTarget;
  EXPECT_EQ(check_bake_params(p, &field), FRUSTA_OK);
  EXPECT_EQ(field, BakeField::kNone);
  p.branching = int64_t{1} << 40;  // as frusta-bake parses it: not narrowed to a valid 0
  EXPECT_EQ(check_bake_params(p, &field), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(field, BakeField::kBranching);
  EXPECT_NE(std::string(frusta_last_error()).find("1099511627776"), std::string::npos);
  p = BakeParams{};
  p.error_samples = kMaxErrorSamples + 1;
  EXPECT_EQ(check_bake_params(p, &field), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(field, BakeField::kSamples);
}

// Embree asserts on a ray origin beyond 1.8e18 (exit 134 in a release build): the
// queries answer such points, and NaN, themselves
TEST(BakeLimits, MeshQueriesNeverHandEmbreeAPointItAbortsOn) {
  const TriangleMesh box = scenes::make_box(vec3(0.1));
  std::unique_ptr<MeshQueries> q;
  ASSERT_EQ(MeshQueries::create(box, &q), FRUSTA_OK);
  for (double far : {1e19, 1e38, 1e300, -1e300}) {
    const vec3 p(far, 0.0, 0.0);
    EXPECT_FALSE(q->inside(p)) << far;
    // (squares of 1e300 overflow: infinitely far is the answer there)
    EXPECT_GE(q->closest(p).distance, std::fabs(far) * (1.0 - 1e-9)) << far;
    EXPECT_GT(q->signed_distance(p), 0.0);
  }
  const vec3 nan(NAN, 0.0, 0.0), inf(INFINITY, 0.0, 0.0);
  EXPECT_FALSE(q->inside(nan));
  EXPECT_FALSE(q->inside(inf));
  EXPECT_EQ(q->closest(nan).distance, INFINITY);
  // and nearby answers are still Embree's
  EXPECT_TRUE(q->inside(vec3(0.0)));
  EXPECT_NEAR(q->closest(vec3(0.2, 0.0, 0.0)).distance, 0.15, 1e-6);
}

}  // namespace
}  // namespace frusta
