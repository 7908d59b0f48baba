// SPDX-License-Identifier: MIT
// The C ABI's bake call through the baker library: found beside the program, and
// refused with FRUSTA_ERROR_UNAVAILABLE and the reason when it is missing or is not a
// baker (FRUSTA_BAKE_PLUGIN points elsewhere: those run as their own ctest entries,
// since a process loads the baker once).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "frusta/frusta.h"
#include "scenes/cube_mesh.h"

namespace {

using frusta_test::kCubeIndices;
using frusta_test::kCubeVertices;

frusta_result bake_cube(frusta_tree_id* tree) {
  frusta_bake_def def = frusta_default_bake_def();
  def.error_samples = 20000;
  return frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, tree);
}

TEST(capiBakePlugin, BakesThroughTheBakerBesideTheProgram) {
  frusta_tree_id tree{};
  ASSERT_EQ(bake_cube(&tree), FRUSTA_OK) << frusta_last_error();
  frusta_sphere_tree_info info{};
  info.struct_size = sizeof info;
  ASSERT_EQ(frusta_sphere_tree_get_info(tree, &info), FRUSTA_OK);
  EXPECT_EQ(info.target_met, 1);
  EXPECT_GT(info.leaf_count, 8);
  EXPECT_LE(info.uncovered_error, 0.001);
  EXPECT_EQ(frusta_destroy_sphere_tree(tree), FRUSTA_OK);
  // the baker's own errors come back with their message
  frusta_bake_def def = frusta_default_bake_def();
  const int32_t bad[] = {0, 1, 9};
  EXPECT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, bad, 3, &def, &tree),
            FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta_last_error()).find("indices[2] is 9"), std::string::npos)
      << frusta_last_error();
}

// run with FRUSTA_BAKE_PLUGIN=/nonexistent/libfrusta_bake.so
TEST(capiBakePlugin, DISABLED_AMissingBakerIsUnavailableAndTheRestWorks) {
  frusta_tree_id tree{};
  EXPECT_EQ(bake_cube(&tree), FRUSTA_ERROR_UNAVAILABLE);
  const std::string message = frusta_last_error();
  EXPECT_NE(message.find("FRUSTA_BAKE_PLUGIN names /nonexistent/libfrusta_bake.so"), std::string::npos)
      << message;
  EXPECT_EQ(bake_cube(&tree), FRUSTA_ERROR_UNAVAILABLE) << "asked again, the same answer";
  EXPECT_EQ(frusta_check_abi(FRUSTA_ABI_VERSION), FRUSTA_OK);
  EXPECT_STREQ(frusta_result_name(FRUSTA_ERROR_UNAVAILABLE), "FRUSTA_ERROR_UNAVAILABLE");
}

// run with FRUSTA_BAKE_PLUGIN naming a library that is not a baker (the runtime)
TEST(capiBakePlugin, DISABLED_ALibraryThatIsNotABakerIsRefused) {
  frusta_tree_id tree{};
  EXPECT_EQ(bake_cube(&tree), FRUSTA_ERROR_UNAVAILABLE);
  EXPECT_NE(std::string(frusta_last_error()).find("not a Frusta baker"), std::string::npos)
      << frusta_last_error();
}

}  // namespace
