// SPDX-License-Identifier: MIT
// frusta-make-test-objects OUTDIR: bakes the test boxes and prisms (scenes/baked_objects.h)
// into OUTDIR/<name>.frtree, writes OUTDIR/million_leaves.frtree (a generated plate, not
// baked) and then OUTDIR/test_objects.json, each object's figures, last: the build's
// mark that every file is there.
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include <glm/common.hpp>

#include "scenes/baked_objects.h"
#include "core/error.h"
#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace {

// 10^6 leaves, 1 mm apart on a 1 x 1 m plate, for the hostile ABI test (a hand lies on
// it); generated in about a second where baking as many would take minutes
bool write_million_leaves(const std::string& path) {
  std::mt19937_64 rng(16);
  const std::vector<frusta::Sphere> leaves = frusta::testing::plate_leaves(rng, 1000, 1000, 0.001, 0.0008);
  frusta::TreeFile file;
  if (frusta::build_sphere_tree(leaves, frusta::TreeBuildOptions{}, &file.tree) != FRUSTA_OK)
    return false;
  file.bounds_min = frusta::vec3(1e30);
  file.bounds_max = frusta::vec3(-1e30);
  for (const frusta::Sphere& s : leaves) {
    file.bounds_min = glm::min(file.bounds_min, s.center - s.radius);
    file.bounds_max = glm::max(file.bounds_max, s.center + s.radius);
  }
  file.bake.max_leaves = static_cast<int64_t>(leaves.size());
  file.bake.max_depth = file.tree.depth;
  return frusta::save_tree_file(path, file) == FRUSTA_OK;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: frusta-make-test-objects OUTDIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  std::string json = "[\n";
  // saves one baked object and adds its figures (after `shape`, its own fields) to json
  auto save = [&](const char* name, const frusta::TreeFile& file, const std::string& shape,
                  double target_error) {
    const std::string path = dir + "/" + name + ".frtree";
    if (frusta::save_tree_file(path, file) != FRUSTA_OK) {
      std::fprintf(stderr, "frusta-make-test-objects: %s\n", frusta::last_error_message());
      return false;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "  {\"name\": \"%s\", %s\"target_error_m\": %g, "
                  "\"uncovered_error_m\": %.3g, \"protruding_error_m\": %.3g, \"leaves\": %zu, "
                  "\"bake_seconds\": %.3f}",
                  name, shape.c_str(), target_error, file.bake.uncovered_error,
                  file.bake.protruding_error, file.tree.leaves.size(), file.bake.bake_seconds);
    json += std::string(json.size() > 2 ? ",\n" : "") + line;
    return true;
  };
  for (const frusta::scenes::TestBox& box : frusta::scenes::test_boxes()) {
    char size[128];
    std::snprintf(size, sizeof size, "\"size_m\": [%g, %g, %g], ", box.size.x, box.size.y, box.size.z);
    if (!save(box.name, *frusta::scenes::baked_box(box.size, box.target_error), size, box.target_error))
      return 1;
  }
  for (const frusta::scenes::TestPrism& prism : frusta::scenes::test_prisms()) {
    char shape[128];
    std::snprintf(shape, sizeof shape, "\"prism_corners\": %zu, \"length_m\": %g, ",
                  prism.section.size(), prism.length);
    if (!save(prism.name, *frusta::scenes::baked_prism(prism), shape, prism.target_error)) return 1;
  }
  if (!write_million_leaves(dir + "/million_leaves.frtree")) {
    std::fprintf(stderr, "frusta-make-test-objects: million_leaves: %s\n", frusta::last_error_message());
    return 1;
  }
  json += ",\n  {\"name\": \"million_leaves\", \"leaves\": 1000000, \"generated\": true}";
  std::ofstream out(dir + "/test_objects.json");
  out << json << "\n]\n";
  if (!out) {
    std::fprintf(stderr, "frusta-make-test-objects: cannot write %s/test_objects.json\n", dir.c_str());
    return 1;
  }
  return 0;
}
