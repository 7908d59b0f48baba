// SPDX-License-Identifier: MIT
// The host's side of a world's objects: which slots are taken (their ids), the trees
// they hold, and the commands they queue for the stepping side (host_commands.h). A
// removed object's tree is kept until the host has read a step that applied the
// removal, and released here, on the host's thread, never in a step.
//
// Threads: the host.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/id_pool.h"
#include "runtime/host_commands.h"

namespace frusta {

class HostObjects {
 public:
  HostObjects(int32_t capacity, HostCommands& commands);

  // Each checks its input and queues a command; FRUSTA_ERROR_CAPACITY when every slot
  // is taken or the queue is full (step the world), FRUSTA_ERROR_STALE_ID for a handle
  // of nothing present.
  frusta_result add(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                    ObjectHandle* out);
  frusta_result remove(ObjectHandle object);
  frusta_result set_pose(ObjectHandle object, const RigidPose& pose);
  frusta_result set_dynamic(ObjectHandle object, bool dynamic);

  bool is_live(ObjectHandle object) const {
    return object.generation <= 0xFFFF &&
           ids_.is_live(object.slot, static_cast<uint16_t>(object.generation));
  }

  // Drop the trees whose removal the step the host has read applied (`applied`: the
  // number of commands it had applied).
  void release(uint64_t applied);

 private:
  frusta_result check_handle(ObjectHandle object) const;

  int32_t capacity_;
  HostCommands& commands_;
  IdPool ids_;
  std::vector<std::shared_ptr<const TreeFile>> trees_;  // by slot
  // trees of removed objects, with the number of the command that removed them
  std::vector<std::pair<uint64_t, std::shared_ptr<const TreeFile>>> retired_;
};

}  // namespace frusta
