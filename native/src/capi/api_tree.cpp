// SPDX-License-Identifier: MIT
// C ABI: sphere trees (load, save, inspect, query); baking is in api_bake.cpp.
#include <cstring>

#include <glm/gtc/quaternion.hpp>

#include "capi/convert.h"
#include "capi/tree_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"
#include "geometry/contact_test.h"

using namespace frusta;

namespace frusta {
TreeRegistry& tree_registry() {
  static TreeRegistry registry("sphere tree");
  return registry;
}
}  // namespace frusta

FRUSTA_API frusta_result frusta_create_sphere_tree_from_file(const char* path,
                                                             frusta_tree_id* out_tree) {
  if (frusta_result r = check_pointer(path, "path")) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  return guarded("frusta_create_sphere_tree_from_file", [&] {
    auto tree = std::make_unique<TreeObject>();
    if (frusta_result r = load_tree_file(path, &tree->file)) return r;
    const BakeRecord& b = tree->file.bake;
    tree->target_met = b.uncovered_error <= b.target_error && b.protruding_error <= b.target_error;
    return tree_registry().add(std::move(tree), out_tree);
  });
}

FRUSTA_API frusta_result frusta_create_sphere_tree_from_memory(const void* data, int64_t size,
                                                               frusta_tree_id* out_tree) {
  if (frusta_result r = check_pointer(data, "data")) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  if (size < 0 || static_cast<uint64_t>(size) > kMaxTreeFileBytes)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "size is %lld, must be 0..%zu (the largest valid tree)",
                static_cast<long long>(size), kMaxTreeFileBytes);
  return guarded("frusta_create_sphere_tree_from_memory", [&] {
    auto tree = std::make_unique<TreeObject>();
    if (frusta_result r = decode_tree_file(static_cast<const uint8_t*>(data),
                                           static_cast<size_t>(size), "data", &tree->file))
      return r;
    const BakeRecord& b = tree->file.bake;
    tree->target_met = b.uncovered_error <= b.target_error && b.protruding_error <= b.target_error;
    return tree_registry().add(std::move(tree), out_tree);
  });
}

FRUSTA_API frusta_result frusta_sphere_tree_save(frusta_tree_id tree, const char* path) {
  TreeObject* t = nullptr;
  if (frusta_result r = tree_registry().find(tree, &t)) return r;
  if (frusta_result r = check_pointer(path, "path")) return r;
  return guarded("frusta_sphere_tree_save", [&] { return save_tree_file(path, t->file); });
}

FRUSTA_API frusta_result frusta_destroy_sphere_tree(frusta_tree_id tree) {
  return tree_registry().destroy(tree);
}

FRUSTA_API int32_t frusta_sphere_tree_is_valid(frusta_tree_id tree) {
  return tree_registry().is_valid(tree) ? 1 : 0;
}

FRUSTA_API frusta_result frusta_sphere_tree_get_info(frusta_tree_id tree,
                                                     frusta_sphere_tree_info* info) {
  TreeObject* t = nullptr;
  if (frusta_result r = tree_registry().find(tree, &t)) return r;
  if (frusta_result r = check_out_struct(info, "info", "frusta_sphere_tree_info")) return r;
  const TreeFile& f = t->file;
  info->branching = f.tree.branching;
  info->depth = f.tree.depth;
  info->leaf_count = static_cast<int32_t>(f.tree.leaves.size());
  info->node_count = static_cast<int32_t>(f.tree.nodes.size());
  info->triangle_count = f.bake.triangle_count;
  store(f.bounds_min, info->bounds_min);
  store(f.bounds_max, info->bounds_max);
  info->target_error = f.bake.target_error;
  info->uncovered_error = f.bake.uncovered_error;
  info->protruding_error = f.bake.protruding_error;
  info->bake_seconds = f.bake.bake_seconds;
  info->error_samples = f.bake.error_samples;
  info->target_met = t->target_met ? 1 : 0;
  info->reserved0 = 0;
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_sphere_tree_get_leaves(frusta_tree_id tree, frusta_sphere* out,
                                                       int32_t capacity, int32_t* out_count) {
  TreeObject* t = nullptr;
  if (frusta_result r = tree_registry().find(tree, &t)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  const std::vector<Sphere>& leaves = t->file.tree.leaves;
  const int32_t count = static_cast<int32_t>(leaves.size());
  return fill_output_array(capacity, count, out_count, [&](int32_t i) {
    store(leaves[static_cast<size_t>(i)].center, out[i].center);
    out[i].radius = leaves[static_cast<size_t>(i)].radius;
  });
}

FRUSTA_API frusta_result frusta_sphere_tree_query_segment(frusta_tree_id tree,
                                                          const frusta_pose* pose,
                                                          const frusta_segment* segment,
                                                          double margin, int32_t max_level,
                                                          frusta_tree_hit* out, int32_t capacity,
                                                          int32_t* out_count) {
  TreeObject* t = nullptr;
  if (frusta_result r = tree_registry().find(tree, &t)) return r;
  Pose p;
  if (pose)
    if (frusta_result r = read_pose(pose, "pose", &p)) return r;
  Segment world;
  if (frusta_result r = read_segment(segment, "segment", &world)) return r;
  if (frusta_result r = check_range(margin, 0.0, kMaxCoordinate, false, "margin")) return r;
  if (max_level < -1 || max_level > kMaxTreeDepth)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_level is %d, must be -1 (leaves) or 0..%d",
                max_level, kMaxTreeDepth);
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;

  RigidPose rigid;
  rigid.position = p.position;
  rigid.rotation = glm::mat3_cast(p.rotation);
  const SphereTree& st = t->file.tree;
  const SegmentFrame frame = make_segment_frame(to_object_frame(rigid, world));
  int32_t written = 0;
  const TreeQueryStats stats = walk_tree(
      st, [&](const Sphere& s) { return may_touch(frame, s, margin); }, max_level,
      [&](const TreeHit& h) {
        if (written >= capacity) return;
        const Sphere local = h.leaf >= 0 ? st.leaves[static_cast<size_t>(h.leaf)] : st.node_sphere(h.node);
        frusta_tree_hit& o = out[written++];
        o.node = h.node;
        o.leaf = h.leaf;
        store(rigid.position + rigid.rotation * local.center, o.sphere.center);
        o.sphere.radius = local.radius;
      });
  *out_count = stats.hits;
  return FRUSTA_OK;
}
