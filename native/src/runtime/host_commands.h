// SPDX-License-Identifier: MIT
// The host's end of a world's one command queue: objects and hands queue their
// commands here, in one order, for the stepping side to apply at its next step
// boundary. A command's number is the count queued up to and with it; each step
// publishes how many it has applied, so the host frees what a removal let go of once
// it has read a step past the removal's number (host_objects.h, host_hands.h).
//
// Threads: push and pushed from the host; pop from the stepping thread.
#pragma once

#include <cstdint>

#include "core/base.h"
#include "core/spsc_queue.h"
#include "runtime/world_command.h"

namespace frusta {

class HostCommands {
 public:
  explicit HostCommands(int32_t capacity) : queue_(static_cast<size_t>(capacity)) {}
  HostCommands(const HostCommands&) = delete;
  HostCommands& operator=(const HostCommands&) = delete;

  // FRUSTA_ERROR_CAPACITY when the queue is full (step the world): nothing is queued.
  frusta_result push(const WorldCommand& command);
  // The number of the last command queued (0: none yet).
  uint64_t pushed() const { return pushed_; }

  // The stepping side: the oldest command not applied yet; false when none is left.
  bool pop(WorldCommand& command) { return queue_.pop(command); }

 private:
  SpscQueue<WorldCommand> queue_;
  uint64_t pushed_ = 0;
};

}  // namespace frusta
