// SPDX-License-Identifier: MIT
// The host's side of a world's objects: which slots are taken (their ids), the trees
// they hold, and the commands queued for the stepping side. A removed object's tree
// is kept until the stepping side has applied the removal, and released here, on the
// host's thread, never in a step.
//
// Threads: the host calls everything but commands().pop, which the stepping thread
// calls, and applied(), which it bumps.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/id_pool.h"
#include "core/spsc_queue.h"
#include "runtime/object_command.h"

namespace frusta {

class HostObjects {
 public:
  HostObjects(int32_t capacity, int32_t command_capacity);

  // Each checks its input and queues a command; FRUSTA_ERROR_CAPACITY when every slot
  // is taken or the queue is full (step the world), FRUSTA_ERROR_STALE_ID for a handle
  // of nothing present.
  frusta_result add(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                    ObjectHandle* out);
  frusta_result remove(ObjectHandle object);
  frusta_result set_pose(ObjectHandle object, const RigidPose& pose);
  frusta_result set_dynamic(ObjectHandle object, bool dynamic);

  // Drop the trees whose removal the stepping side has applied.
  void release_retired();

  // The stepping side: the queue to pop, and the count of commands applied to bump.
  SpscQueue<ObjectCommand>& commands() { return commands_; }
  void mark_applied(uint64_t count) { applied_.fetch_add(count, std::memory_order_release); }

 private:
  frusta_result check_handle(ObjectHandle object) const;
  frusta_result queue(const ObjectCommand& command);

  int32_t capacity_;
  IdPool ids_;
  std::vector<std::shared_ptr<const TreeFile>> trees_;  // by slot
  uint64_t pushed_ = 0;  // commands queued so far
  // trees of removed objects, with the count of commands that must be applied first
  std::vector<std::pair<uint64_t, std::shared_ptr<const TreeFile>>> retired_;
  SpscQueue<ObjectCommand> commands_;
  std::atomic<uint64_t> applied_{0};
};

}  // namespace frusta
