// SPDX-License-Identifier: MIT
// C ABI: baking a sphere tree from triangles, by the baker library where it exists
// (bake/bake_plugin.h): the runtime itself needs no Embree.
#include "bake/bake_params.h"
#include "capi/bake_plugin_loader.h"
#include "capi/convert.h"
#include "capi/tree_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"

using namespace frusta;

FRUSTA_API frusta_bake_def frusta_default_bake_def(void) {
  frusta_bake_def def = blank_def<frusta_bake_def>();
  copy_bake_params(BakeParams(), def);
  return def;
}

FRUSTA_API frusta_result frusta_create_sphere_tree_from_mesh(
    const float* vertices, int32_t vertex_count, const int32_t* indices, int32_t index_count,
    const frusta_bake_def* def, frusta_tree_id* out_tree) {
  if (frusta_result r = check_def_input(def, "frusta_bake_def")) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  // the parameters' one check, before the baker is loaded (bake/bake_params.h)
  BakeParams params;
  copy_bake_params(*def, params);
  if (frusta_result r = check_bake_params(params)) return r;
  return guarded("frusta_create_sphere_tree_from_mesh", [&] {
    std::string why;
    const BakePlugin* plugin = bake_plugin(&why);
    if (plugin == nullptr) return fail(FRUSTA_ERROR_UNAVAILABLE, "cannot bake: %s", why.c_str());
    uint8_t* bytes = nullptr;
    int64_t size = 0;
    int32_t target_met = 0;
    char error[1024] = "";
    frusta_bake_plugin_params plugin_params;
    copy_bake_params(params, plugin_params);
    const frusta_result r = plugin->bake(vertices, vertex_count, indices, index_count,
                                         &plugin_params, &bytes, &size, &target_met, error,
                                         sizeof error);
    if (r != FRUSTA_OK) return fail(r, "%s", error);  // the baker's message, without its code
    auto tree = std::make_unique<TreeObject>();
    const frusta_result decoded =
        decode_tree_file(bytes, static_cast<size_t>(size), "the baked tree", &tree->file);
    plugin->free(bytes);
    if (decoded != FRUSTA_OK) return decoded;  // the two libraries disagree: named by decode
    tree->target_met = target_met != 0;
    return tree_registry().add(std::move(tree), out_tree);
  });
}
