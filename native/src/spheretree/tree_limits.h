// SPDX-License-Identifier: MIT
// Bounds every tree obeys, checked by the builder and the loader. They bound the
// query stack and every allocation a (possibly hostile) file can cause.
#pragma once

#include <cstdint>

namespace frusta {

constexpr int32_t kMaxBranching = 16;
constexpr int32_t kMaxTreeDepth = 40;
constexpr int64_t kMaxLeaves = int64_t{1} << 24;  // 16 M spheres, 640 MB of tree
// a tree has fewer inner nodes than leaves when every inner node has >= 2 children;
// chains of single children are allowed only down to the depth limit
constexpr int64_t kMaxNodes = 2 * kMaxLeaves + kMaxTreeDepth;

}  // namespace frusta
