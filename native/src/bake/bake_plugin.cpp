// SPDX-License-Identifier: MIT
// The baker library's side of bake_plugin.h: mesh in, .frtree bytes out.
#include "bake/bake_plugin.h"

#include <cstdlib>
#include <cstring>

#include "bake/bake_params.h"
#include "bake/baker.h"
#include "core/error.h"
#include "core/validate.h"

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

frusta_result bake(const float* vertices, int32_t vertex_count, const int32_t* indices,
                   int32_t index_count, const frusta_bake_plugin_params& params,
                   frusta_bake_plugin_progress progress, void* context,
                   std::vector<uint8_t>* file, bool* target_met) {
  TriangleMesh mesh;
  if (frusta_result r = read_mesh(vertices, vertex_count, indices, index_count, &mesh)) return r;
  BakeParams p;
  copy_bake_params(params, p);
  TreeFile tree;
  ProgressFn report;
  if (progress != nullptr)
    report = [progress, context](double fraction) { return progress(fraction, context) == 0; };
  if (frusta_result r = bake_sphere_tree(mesh, p, report, &tree, target_met)) return r;
  *file = encode_tree_file(tree);
  return FRUSTA_OK;
}

}  // namespace

FRUSTA_BAKE_PLUGIN_API int32_t frusta_bake_plugin_version(void) {
  return FRUSTA_BAKE_PLUGIN_VERSION;
}

FRUSTA_BAKE_PLUGIN_API frusta_result frusta_bake_plugin_bake(
    const float* vertices, int32_t vertex_count, const int32_t* indices, int32_t index_count,
    const frusta_bake_plugin_params* params, frusta_bake_plugin_progress progress,
    void* context, uint8_t** out_tree_file, int64_t* out_size, int32_t* out_target_met,
    char* error, int32_t error_capacity) {
  frusta_result r = guarded("frusta_create_sphere_tree_from_mesh", [&] {
    if (frusta_result p = check_pointer(params, "params")) return p;
    if (frusta_result p = check_pointer(out_tree_file, "out_tree_file")) return p;
    std::vector<uint8_t> file;
    bool target_met = false;
    if (frusta_result b = bake(vertices, vertex_count, indices, index_count, *params, progress,
                               context, &file, &target_met))
      return b;
    auto* bytes = static_cast<uint8_t*>(std::malloc(file.size()));
    if (bytes == nullptr)
      return fail(FRUSTA_ERROR_OUT_OF_MEMORY, "no memory for a %zu-byte tree", file.size());
    std::memcpy(bytes, file.data(), file.size());
    *out_tree_file = bytes;
    *out_size = static_cast<int64_t>(file.size());
    *out_target_met = target_met ? 1 : 0;
    return FRUSTA_OK;
  });
  if (r != FRUSTA_OK && error != nullptr && error_capacity > 0) {
    // the runtime's fail() adds the code again
    std::strncpy(error, last_error_detail(r), static_cast<size_t>(error_capacity) - 1);
    error[error_capacity - 1] = 0;
  }
  return r;
}

FRUSTA_BAKE_PLUGIN_API void frusta_bake_plugin_free(uint8_t* tree_file) { std::free(tree_file); }
