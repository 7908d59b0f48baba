// SPDX-License-Identifier: MIT
// What the host's side of a world tells its stepping side about objects, through a
// lock-free queue: applied at the next step boundary, in order.
#pragma once

#include <cstdint>

#include "runtime/world_def.h"
#include "spheretree/tree_file.h"

namespace frusta {

enum class ObjectCommandKind : int32_t { kAdd, kRemove, kPose, kDynamic };

struct ObjectCommand {
  ObjectCommandKind kind = ObjectCommandKind::kAdd;
  int32_t slot = -1;
  uint32_t generation = 0;
  ObjectDef def;  // kAdd: all of it; kPose: the pose; kDynamic: the flag
  const TreeFile* tree = nullptr;  // kAdd: the host side keeps it alive while used
};

}  // namespace frusta
