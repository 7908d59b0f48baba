// SPDX-License-Identifier: MIT
#include "scenes/baked_objects.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/error.h"
#include "meshes/meshes.h"

#if defined(FRUSTA_HAVE_BAKER)
#include "bake/baker.h"
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

// the object of `list` called `name`; an unknown name throws
template <class Object>
const Object& named(const std::vector<Object>& list, const std::string& name, const char* kind) {
  for (const Object& object : list)
    if (name == object.name) return object;
  throw std::invalid_argument("no test " + std::string(kind) + " named " + name +
                              " (tests/scenes/baked_objects.cpp)");
}

// a mesh baked now to `target_error`; `what` names it in the error
std::shared_ptr<const TreeFile> bake_now([[maybe_unused]] const TriangleMesh& mesh,
                                         [[maybe_unused]] double target_error, const char* what) {
#if defined(FRUSTA_HAVE_BAKER)
  auto file = std::make_shared<TreeFile>();
  BakeParams params;
  params.target_error = target_error;
  bool met = false;
  if (bake_sphere_tree(mesh, params, nullptr, file.get(), &met) != FRUSTA_OK)
    throw std::runtime_error(std::string("baking ") + what + ": " + frusta::last_error_message());
  return file;
#else
  throw std::runtime_error(std::string("baking ") + what + " needs the baker (Embree), which this build lacks");
#endif
}

}  // namespace

std::shared_ptr<const TreeFile> sample_tree(const std::string& name) {
  return load_once(FRUSTA_SAMPLE_OBJECTS_DIR, name, "frusta_sample_objects");
}

ObjectDef object_at(const vec3& at, double mass, bool dynamic) {
  ObjectDef def;
  def.pose.position = at;
  def.dynamic = dynamic;
  def.mass = mass;
  def.inertia = vec3(mass * 0.03 * 0.03 / 6.0);
  return def;
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

const TestBox& test_box_spec(const std::string& name) { return named(test_boxes(), name, "box"); }

std::shared_ptr<const TreeFile> test_box(const std::string& name) {
  return load_once(FRUSTA_TEST_OBJECTS_DIR, test_box_spec(name).name, "frusta_test_objects");
}

std::shared_ptr<const TreeFile> baked_box(const vec3& size, double target_error) {
  return bake_now(make_box(size, 4), target_error, "a box");
}

const std::vector<TestPrism>& test_prisms() {
  static const std::vector<TestPrism> prisms = [] {
    constexpr double kPi = 3.14159265358979323846;
    std::vector<std::pair<double, double>> hexagon;
    for (int k = 0; k < 6; ++k)  // corner 0 on top
      hexagon.emplace_back(0.02 * std::cos(kPi / 2 + k * kPi / 3), 0.02 * std::sin(kPi / 2 + k * kPi / 3));
    const double leg = 0.04, rise = leg * std::tan(kPi / 6);
    return std::vector<TestPrism>{
        {"hex_prism", hexagon, 0.06, 0.0005},
        {"edge_box", {{0.015, 0.015}, {-0.015, 0.015}, {-0.015, -0.015}, {0.015, -0.015}}, 0.06, 0.0005},
        {"wedge", {{0.5 * leg, 0.0}, {-0.5 * leg, rise}, {-0.5 * leg, 0.0}}, 0.06, 0.0005},
    };
  }();
  return prisms;
}

const TestPrism& test_prism_spec(const std::string& name) { return named(test_prisms(), name, "prism"); }

std::shared_ptr<const TreeFile> test_prism(const std::string& name) {
  return load_once(FRUSTA_TEST_OBJECTS_DIR, test_prism_spec(name).name, "frusta_test_objects");
}

std::shared_ptr<const TreeFile> baked_prism(const TestPrism& prism) {
  return bake_now(make_prism(prism.section, prism.length), prism.target_error, prism.name);
}

}  // namespace frusta::scenes
