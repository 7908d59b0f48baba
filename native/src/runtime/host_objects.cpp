// SPDX-License-Identifier: MIT
#include "runtime/host_objects.h"

#include <algorithm>

#include "core/error.h"

namespace frusta {

HostObjects::HostObjects(int32_t capacity, int32_t command_capacity)
    : capacity_(capacity),
      ids_(capacity),
      trees_(static_cast<size_t>(capacity)),
      commands_(static_cast<size_t>(command_capacity)) {}

frusta_result HostObjects::queue(const ObjectCommand& command) {
  if (!commands_.push(command))
    return fail(FRUSTA_ERROR_CAPACITY, "the world's command queue is full (%zu): step the world",
                commands_.capacity());
  ++pushed_;
  return FRUSTA_OK;
}

void HostObjects::release_retired() {
  const uint64_t applied = applied_.load(std::memory_order_acquire);
  retired_.erase(std::remove_if(retired_.begin(), retired_.end(),
                                [&](const auto& r) { return r.first <= applied; }),
                 retired_.end());
}

frusta_result HostObjects::check_handle(ObjectHandle object) const {
  if (object.generation > 0xFFFF ||
      !ids_.is_live(object.slot, static_cast<uint16_t>(object.generation)))
    return fail(FRUSTA_ERROR_STALE_ID, "object {slot=%d, generation=%u} names no object in this world",
                object.slot, object.generation);
  return FRUSTA_OK;
}

frusta_result HostObjects::add(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                               ObjectHandle* out) {
  release_retired();
  if (!tree) return fail(FRUSTA_ERROR_NULL_POINTER, "tree is null");
  if (frusta_result r = check_object_def(def)) return r;
  int32_t slot = 0;
  uint16_t generation = 0;
  if (!ids_.acquire(&slot, &generation))
    return fail(FRUSTA_ERROR_CAPACITY, "the world holds max_objects (%d) objects", capacity_);
  ObjectCommand c;
  c.kind = ObjectCommandKind::kAdd;
  c.slot = slot;
  c.generation = generation;
  c.def = def;
  c.tree = tree.get();
  if (frusta_result r = queue(c)) {
    ids_.release(slot);  // never named to anyone: its next generation is as good
    return r;
  }
  trees_[static_cast<size_t>(slot)] = std::move(tree);
  *out = {slot, c.generation};
  return FRUSTA_OK;
}

frusta_result HostObjects::remove(ObjectHandle object) {
  release_retired();
  if (frusta_result r = check_handle(object)) return r;
  ObjectCommand c;
  c.kind = ObjectCommandKind::kRemove;
  c.slot = object.slot;
  if (frusta_result r = queue(c)) return r;
  const size_t slot = static_cast<size_t>(object.slot);
  // the stepping thread may use the tree until it applies this command
  retired_.emplace_back(pushed_, std::move(trees_[slot]));
  trees_[slot].reset();
  ids_.release(object.slot);
  return FRUSTA_OK;
}

frusta_result HostObjects::set_pose(ObjectHandle object, const RigidPose& pose) {
  if (frusta_result r = check_handle(object)) return r;
  if (frusta_result r = check_rigid_pose(pose, "pose")) return r;
  ObjectCommand c;
  c.kind = ObjectCommandKind::kPose;
  c.slot = object.slot;
  c.def.pose = pose;
  return queue(c);
}

frusta_result HostObjects::set_dynamic(ObjectHandle object, bool dynamic) {
  if (frusta_result r = check_handle(object)) return r;
  ObjectCommand c;
  c.kind = ObjectCommandKind::kDynamic;
  c.slot = object.slot;
  c.def.dynamic = dynamic;
  return queue(c);
}

}  // namespace frusta
