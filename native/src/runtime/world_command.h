// SPDX-License-Identifier: MIT
// What the host's side of a world tells its stepping side about objects and hands,
// through one lock-free queue: applied at the next step boundary, in order.
#pragma once

#include <cstdint>

#include "runtime/world_def.h"
#include "spheretree/tree_file.h"

namespace frusta {

class HandPipeline;

enum class CommandKind : int32_t {
  kAddObject,
  kRemoveObject,
  kObjectPose,
  kObjectDynamic,
  kAddHand,
  kRemoveHand,
};

struct WorldCommand {
  CommandKind kind = CommandKind::kAddObject;
  int32_t slot = -1;  // the object's or the hand's
  uint32_t generation = 0;  // kAddObject, kAddHand
  ObjectDef def;  // kAddObject: all of it; kObjectPose: the pose; kObjectDynamic: the flag
  const TreeFile* tree = nullptr;  // kAddObject: the host side keeps it alive while used
  HandPipeline* hand = nullptr;    // kAddHand: built by the host side, which frees it
                                   // once no step nor read can see it
};

}  // namespace frusta
