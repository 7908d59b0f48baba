// SPDX-License-Identifier: MIT
#include "scenes/baked_objects.h"

#include <map>
#include <stdexcept>

#include "core/error.h"

#if defined(FRUSTA_HAVE_BAKER)
#include "bake/baker.h"
#include "meshes/meshes.h"
#endif

namespace frusta::scenes {

namespace {

// `dir`/`name`.frtree, read once per process
std::shared_ptr<const TreeFile> load_once(const std::string& dir, const std::string& name,
                                          const char* built_by) {
  static std::map<std::string, std::shared_ptr<const TreeFile>> cache;
  const std::string path = dir + "/" + name + ".frtree";
  auto it = cache.find(path);
  if (it != cache.end()) return it->second;
  auto file = std::make_shared<TreeFile>();
  if (load_tree_file(path, file.get()) != FRUSTA_OK)
    throw std::runtime_error(path + ": " + frusta::last_error_message() + " (built by " + built_by + ")");
  cache[path] = file;
  return file;
}

}  // namespace

std::shared_ptr<const TreeFile> sample_tree(const std::string& name) {
  return load_once(FRUSTA_SAMPLE_OBJECTS_DIR, name, "frusta_sample_objects");
}

const std::vector<TestBox>& test_boxes() {
  static const std::vector<TestBox> boxes = {
      {"press_box", vec3(0.03), 0.0005},
      {"fingertip_box", vec3(0.02), 0.0002},
      {"lifted_box", vec3(0.05), 0.0005},
      {"pinch_plate", vec3(0.03, 0.03, 0.004), 0.001},
      {"room_box", vec3(0.40, 0.30, 0.16), 0.004},
  };
  return boxes;
}

const TestBox& test_box_spec(const std::string& name) {
  for (const TestBox& box : test_boxes())
    if (name == box.name) return box;
  throw std::invalid_argument("no test box named " + name + " (tests/scenes/baked_objects.cpp)");
}

std::shared_ptr<const TreeFile> test_box(const std::string& name) {
  return load_once(FRUSTA_TEST_OBJECTS_DIR, test_box_spec(name).name, "frusta_test_objects");
}

std::shared_ptr<const TreeFile> baked_box(const vec3& size, double target_error) {
#if defined(FRUSTA_HAVE_BAKER)
  auto file = std::make_shared<TreeFile>();
  BakeParams params;
  params.target_error = target_error;
  bool met = false;
  if (bake_sphere_tree(make_box(size, 4), params, nullptr, file.get(), &met) != FRUSTA_OK)
    throw std::runtime_error(std::string("baking a box: ") + frusta::last_error_message());
  return file;
#else
  (void)size;
  (void)target_error;
  throw std::runtime_error("baked_box needs the baker (Embree), which this build lacks");
#endif
}

}  // namespace frusta::scenes
