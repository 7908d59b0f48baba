// SPDX-License-Identifier: MIT
// What instancing a glTF scene asks for, counted on its JSON before any buffer is
// read: node instances, triangles and vertices over the node graph (a subtree shared
// by many parents is counted once, with saturating sums, so 2^24 instances cost 24
// visits), refused beyond GltfLimits' budgets, with cycles and nesting beyond
// kMaxNodeDepth. Integers are read as tinygltf reads them (any JSON integer, cast to
// int), so the count describes the model the loader will walk.
#pragma once

#include <string>

#include "core/base.h"
#include "gltf_json.h"

namespace frusta {

// FRUSTA_OK, or FRUSTA_ERROR_FILE_FORMAT naming `path` and the budget or node at fault.
frusta_result check_scene_budget(const Json& root, const std::string& path);

}  // namespace frusta
