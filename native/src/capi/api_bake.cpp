// SPDX-License-Identifier: MIT
// C ABI: baking a sphere tree from triangles (Embree; built with the baker).
#include <cstring>

#include "bake/baker.h"
#include "capi/convert.h"
#include "capi/tree_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"

using namespace frusta;

namespace {

// a mesh larger than this is a caller's mistake (or garbage), not a game asset
constexpr int32_t kMaxBakeVertices = 1 << 26;

frusta_result read_mesh(const float* vertices, int32_t vertex_count, const int32_t* indices,
                        int32_t index_count, TriangleMesh* mesh) {
  if (frusta_result r = check_pointer(vertices, "vertices")) return r;
  if (frusta_result r = check_pointer(indices, "indices")) return r;
  if (vertex_count < 3 || vertex_count > kMaxBakeVertices)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "vertex_count is %d, must be 3..%d", vertex_count,
                kMaxBakeVertices);
  if (index_count < 3 || index_count % 3 != 0 || index_count / 3 > kMaxBakeVertices)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "index_count is %d, must be a positive multiple of 3",
                index_count);
  mesh->vertices.resize(static_cast<size_t>(vertex_count));
  for (size_t i = 0; i < mesh->vertices.size(); ++i)
    mesh->vertices[i] = vec3(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
  mesh->triangles.resize(static_cast<size_t>(index_count / 3));
  for (size_t t = 0; t < mesh->triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k) {
      const int32_t index = indices[3 * t + k];
      if (index < 0 || index >= vertex_count)
        return fail(FRUSTA_ERROR_OUT_OF_RANGE, "indices[%zu] is %d, must be 0..%d", 3 * t + k,
                    index, vertex_count - 1);
      mesh->triangles[t][k] = static_cast<uint32_t>(index);
    }
  return check_mesh(*mesh, "mesh");
}

}  // namespace

FRUSTA_API frusta_bake_def frusta_default_bake_def(void) {
  const BakeParams defaults;
  frusta_bake_def def;
  std::memset(&def, 0, sizeof def);
  def.struct_size = sizeof(frusta_bake_def);
  def.branching = defaults.branching;
  def.target_error = defaults.target_error;
  def.max_leaves = defaults.max_leaves;
  def.max_depth = defaults.max_depth;
  def.error_samples = defaults.error_samples;
  def.seed = defaults.seed;
  def.internal_value = kDefCookie;
  return def;
}

FRUSTA_API frusta_result frusta_bake_sphere_tree(const float* vertices, int32_t vertex_count,
                                                 const int32_t* indices, int32_t index_count,
                                                 const frusta_bake_def* def,
                                                 frusta_tree_id* out_tree) {
  if (frusta_result r = check_def_input(def, "frusta_bake_def")) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  return guarded("frusta_bake_sphere_tree", [&] {
    TriangleMesh mesh;
    if (frusta_result r = read_mesh(vertices, vertex_count, indices, index_count, &mesh)) return r;
    BakeParams params;
    params.target_error = def->target_error;
    params.max_leaves = def->max_leaves;
    params.branching = def->branching;
    params.max_depth = def->max_depth;
    params.error_samples = def->error_samples;
    params.seed = def->seed;
    auto tree = std::make_unique<TreeObject>();
    if (frusta_result r = bake_sphere_tree(mesh, params, nullptr, &tree->file, &tree->target_met))
      return r;
    return tree_registry().add(std::move(tree), out_tree);
  });
}

