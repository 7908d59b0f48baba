// SPDX-License-Identifier: MIT
#include "gltf_scene_budget.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "gltf_error.h"
#include "gltf_loader.h"

namespace frusta {

namespace {

constexpr int kTriangles = TINYGLTF_MODE_TRIANGLES;

uint64_t add_saturated(uint64_t a, uint64_t b) {
  return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max()
                                                      : a + b;
}

class ScenePlan {
 public:
  ScenePlan(const Json& root, const std::string& path) : root_(root), path_(path) {}

  frusta_result check() {
    const Json* nodes = array(root_, "nodes");
    node_count_ = nodes ? nodes->size() : 0;
    state_.assign(node_count_, kNew);
    memo_.assign(node_count_, {});
    std::vector<int> roots;
    const Json* scenes = array(root_, "scenes");
    if (scenes && !scenes->empty()) {
      int scene = 0;
      if (const Json* s = member(root_, "scene")) integer(*s, &scene);
      if (scene < 0) scene = 0;
      if (static_cast<size_t>(scene) >= scenes->size()) return FRUSTA_OK;  // the loader says so
      roots = integers((*scenes)[static_cast<size_t>(scene)], "nodes");
    } else {
      for (size_t i = 0; i < node_count_; ++i) roots.push_back(static_cast<int>(i));
    }
    Totals total;
    for (int r : roots) {
      Totals t;
      if (frusta_result e = visit(r, 0, &t)) return e;
      total.add(t);
    }
    if (total.instances > GltfLimits::kMaxNodeInstances)
      return over("node instances", total.instances, GltfLimits::kMaxNodeInstances);
    if (total.triangles > GltfLimits::kMaxTriangles)
      return over("triangles", total.triangles, GltfLimits::kMaxTriangles);
    if (total.vertices > GltfLimits::kMaxVertices)
      return over("vertices", total.vertices, GltfLimits::kMaxVertices);
    return FRUSTA_OK;
  }

 private:
  struct Totals {
    uint64_t instances = 0, triangles = 0, vertices = 0;
    int height = 0;  // levels below
    void add(const Totals& t) {
      instances = add_saturated(instances, t.instances);
      triangles = add_saturated(triangles, t.triangles);
      vertices = add_saturated(vertices, t.vertices);
    }
  };
  enum State : uint8_t { kNew, kOpen, kDone };

  static const Json* member(const Json& o, const char* key) {
    if (!o.is_object()) return nullptr;
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }
  static const Json* array(const Json& o, const char* key) {
    const Json* a = member(o, key);
    return a && a->is_array() ? a : nullptr;
  }
  static bool integer(const Json& v, int* out) {
    if (!v.is_number_integer()) return false;
    *out = static_cast<int>(v.get<int64_t>());
    return true;
  }
  // an integer array as tinygltf keeps it: the elements up to the first non-integer
  static std::vector<int> integers(const Json& o, const char* key) {
    std::vector<int> out;
    if (const Json* a = array(o, key))
      for (const Json& v : *a) {
        int i = 0;
        if (!integer(v, &i)) break;
        out.push_back(i);
      }
    return out;
  }
  // an accessor's count, 0 when there is no such accessor (the loader reports it)
  uint64_t accessor_count(int index) const {
    const Json* accessors = array(root_, "accessors");
    if (!accessors || index < 0 || static_cast<size_t>(index) >= accessors->size()) return 0;
    const Json* count = member((*accessors)[static_cast<size_t>(index)], "count");
    return count && count->is_number_unsigned() ? count->get<uint64_t>() : 0;
  }

  // the triangles and vertices one instance of a mesh adds, as the Reader reads them;
  // a single accessor over the whole budget is named (its count may be 2^62)
  frusta_result mesh_totals(int mesh, Totals* t) {
    const Json* meshes = array(root_, "meshes");
    if (!meshes || mesh < 0 || static_cast<size_t>(mesh) >= meshes->size()) return FRUSTA_OK;
    const Json* primitives = array((*meshes)[static_cast<size_t>(mesh)], "primitives");
    if (!primitives) return FRUSTA_OK;
    int k = -1;
    for (const Json& p : *primitives) {
      const Json* attributes = member(p, "attributes");
      if (!attributes || !attributes->is_object()) continue;  // tinygltf drops it
      bool all_integers = true;
      for (const Json& a : *attributes) all_integers = all_integers && a.is_number_integer();
      if (!all_integers) continue;
      ++k;
      int mode = kTriangles, indices = -1, position = -1;
      if (const Json* m = member(p, "mode")) integer(*m, &mode);
      if (mode >= 0 && mode != kTriangles) continue;
      if (const Json* i = member(p, "indices")) integer(*i, &indices);
      if (const Json* pos = member(*attributes, "POSITION")) integer(*pos, &position);
      const uint64_t vertices = accessor_count(position);
      if (vertices > GltfLimits::kMaxVertices)
        return bad(
            "mesh %d primitive %d: POSITION accessor %d has %llu elements, more than the "
            "%llu vertices the loader takes",
            mesh, k, position, static_cast<unsigned long long>(vertices),
            static_cast<unsigned long long>(GltfLimits::kMaxVertices));
      const uint64_t triangles = (indices >= 0 ? accessor_count(indices) : vertices) / 3;
      if (triangles > GltfLimits::kMaxTriangles)
        return bad(
            "mesh %d primitive %d: index accessor %d has %llu elements, more than the "
            "%llu triangles the loader takes",
            mesh, k, indices, static_cast<unsigned long long>(accessor_count(indices)),
            static_cast<unsigned long long>(GltfLimits::kMaxTriangles));
      t->vertices = add_saturated(t->vertices, vertices);
      t->triangles = add_saturated(t->triangles, triangles);
    }
    return FRUSTA_OK;
  }

  // Memoised: a subtree shared by many parents is counted once and added per use,
  // so 2^24 instances cost 24 visits. Recursion stops at kMaxNodeDepth.
  frusta_result visit(int index, int depth, Totals* out) {
    if (index < 0 || static_cast<size_t>(index) >= node_count_) return FRUSTA_OK;  // reported later
    const size_t i = static_cast<size_t>(index);
    if (state_[i] == kOpen)
      return bad("node %d is its own descendant (its children lead back to it)", index);
    if (state_[i] == kNew) {
      state_[i] = kOpen;
      const Json& node = (*array(root_, "nodes"))[i];
      Totals t;
      t.instances = 1;
      int mesh = -1;
      if (const Json* m = member(node, "mesh")) integer(*m, &mesh);
      if (frusta_result e = mesh_totals(mesh, &t)) return e;
      if (depth >= GltfLimits::kMaxNodeDepth && !integers(node, "children").empty())
        return bad("node %d is nested more than %d deep", index, GltfLimits::kMaxNodeDepth);
      for (int child : integers(node, "children")) {
        Totals c;
        if (frusta_result e = visit(child, depth + 1, &c)) return e;
        t.add(c);
        t.height = std::max(t.height, c.height + (c.instances > 0 ? 1 : 0));
      }
      memo_[i] = t;
      state_[i] = kDone;
    }
    if (depth + memo_[i].height > GltfLimits::kMaxNodeDepth)
      return bad("node %d is nested more than %d deep", index, GltfLimits::kMaxNodeDepth);
    *out = memo_[i];
    return FRUSTA_OK;
  }

  frusta_result over(const char* what, uint64_t asked, uint64_t budget) {
    const std::string count = asked == std::numeric_limits<uint64_t>::max()
                                  ? std::string("2^64 or more")
                                  : std::to_string(asked);
    return bad(
        "the scene asks for %s %s once its nodes are instanced (nodes used more than "
        "once repeat their meshes), over the loader's budget of %llu",
        count.c_str(), what, static_cast<unsigned long long>(budget));
  }

  template <class... Args>
  frusta_result bad(const char* format, Args... args) {
    return gltf_format_error(path_, format, args...);
  }

  const Json& root_;
  const std::string& path_;
  size_t node_count_ = 0;
  std::vector<State> state_;
  std::vector<Totals> memo_;
};

}  // namespace

frusta_result check_scene_budget(const Json& root, const std::string& path) {
  return ScenePlan(root, path).check();
}

}  // namespace frusta
