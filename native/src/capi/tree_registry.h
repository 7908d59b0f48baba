// SPDX-License-Identifier: MIT
// Standalone sphere trees behind frusta_tree_id. A tree is immutable once made, so
// any thread may query it while none destroys it.
#pragma once

#include "capi/registry.h"
#include "spheretree/tree_file.h"

namespace frusta {

struct TreeObject {
  TreeFile file;
  bool target_met = false;
};

using TreeRegistry = Registry<TreeObject, frusta_tree_id>;
TreeRegistry& tree_registry();

}  // namespace frusta
