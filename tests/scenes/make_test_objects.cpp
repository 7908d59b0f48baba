// SPDX-License-Identifier: MIT
// frusta-make-test-objects OUTDIR: bakes the test boxes (scenes/baked_objects.h) into
// OUTDIR/<name>.frtree and writes OUTDIR/test_objects.json, each box's bake figures,
// last: the build's mark that every file is there.
#include <cstdio>
#include <fstream>
#include <string>

#include "scenes/baked_objects.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: frusta-make-test-objects OUTDIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  std::string json = "[\n";
  for (const frusta::scenes::TestBox& box : frusta::scenes::test_boxes()) {
    const auto file = frusta::scenes::baked_box(box.size, box.target_error);
    const std::string path = dir + "/" + box.name + ".frtree";
    if (frusta::save_tree_file(path, *file) != FRUSTA_OK) {
      std::fprintf(stderr, "frusta-make-test-objects: %s\n", frusta_last_error());
      return 1;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "  {\"name\": \"%s\", \"size_m\": [%g, %g, %g], \"target_error_m\": %g, "
                  "\"uncovered_error_m\": %.3g, \"protruding_error_m\": %.3g, \"leaves\": %zu, "
                  "\"bake_seconds\": %.3f}",
                  box.name, box.size.x, box.size.y, box.size.z, box.target_error,
                  file->bake.uncovered_error, file->bake.protruding_error,
                  file->tree.leaves.size(), file->bake.bake_seconds);
    json += std::string(json.size() > 2 ? ",\n" : "") + line;
  }
  std::ofstream out(dir + "/test_objects.json");
  out << json << "\n]\n";
  if (!out) {
    std::fprintf(stderr, "frusta-make-test-objects: cannot write %s/test_objects.json\n", dir.c_str());
    return 1;
  }
  return 0;
}
