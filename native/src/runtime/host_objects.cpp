// SPDX-License-Identifier: MIT
#include "runtime/host_objects.h"

#include <algorithm>

#include "core/error.h"

namespace frusta {

HostObjects::HostObjects(int32_t capacity, HostCommands& commands)
    : capacity_(capacity), commands_(commands), ids_(capacity), trees_(static_cast<size_t>(capacity)) {}

void HostObjects::release(uint64_t applied) {
  retired_.erase(std::remove_if(retired_.begin(), retired_.end(),
                                [&](const auto& r) { return r.first <= applied; }),
                 retired_.end());
}

frusta_result HostObjects::check_handle(ObjectHandle object) const {
  if (!is_live(object))
    return fail(FRUSTA_ERROR_STALE_ID, "object {slot=%d, generation=%u} names no object in this world",
                object.slot, object.generation);
  return FRUSTA_OK;
}

frusta_result HostObjects::add(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                               ObjectHandle* out) {
  if (!tree) return fail(FRUSTA_ERROR_NULL_POINTER, "tree is null");
  if (frusta_result r = check_object_def(def)) return r;
  int32_t slot = 0;
  uint16_t generation = 0;
  if (!ids_.acquire(&slot, &generation))
    return fail(FRUSTA_ERROR_CAPACITY, "the world holds max_objects (%d) objects", capacity_);
  WorldCommand c;
  c.kind = CommandKind::kAddObject;
  c.slot = slot;
  c.generation = generation;
  c.def = def;
  c.tree = tree.get();
  if (frusta_result r = commands_.push(c)) {
    ids_.release(slot);  // never named to anyone: its next generation is as good
    return r;
  }
  trees_[static_cast<size_t>(slot)] = std::move(tree);
  *out = {slot, c.generation};
  return FRUSTA_OK;
}

frusta_result HostObjects::remove(ObjectHandle object) {
  if (frusta_result r = check_handle(object)) return r;
  WorldCommand c;
  c.kind = CommandKind::kRemoveObject;
  c.slot = object.slot;
  if (frusta_result r = commands_.push(c)) return r;
  const size_t slot = static_cast<size_t>(object.slot);
  // the stepping thread may use the tree until it applies this command
  retired_.emplace_back(commands_.pushed(), std::move(trees_[slot]));
  trees_[slot].reset();
  ids_.release(object.slot);
  return FRUSTA_OK;
}

frusta_result HostObjects::set_pose(ObjectHandle object, const RigidPose& pose) {
  if (frusta_result r = check_handle(object)) return r;
  if (frusta_result r = check_rigid_pose(pose, "pose")) return r;
  WorldCommand c;
  c.kind = CommandKind::kObjectPose;
  c.slot = object.slot;
  c.def.pose = pose;
  return commands_.push(c);
}

frusta_result HostObjects::set_dynamic(ObjectHandle object, bool dynamic) {
  if (frusta_result r = check_handle(object)) return r;
  WorldCommand c;
  c.kind = CommandKind::kObjectDynamic;
  c.slot = object.slot;
  c.def.dynamic = dynamic;
  return commands_.push(c);
}

}  // namespace frusta
