// SPDX-License-Identifier: MIT
// The host's side of a world's hands: which slots are taken (their ids), the pipeline
// that solves each hand, and one port per slot for what drives the hand. Adding a hand
// builds its whole pipeline here, on the host's thread, and queues it for the stepping
// side (host_commands.h); removing one closes its port at once and queues the removal.
// The pipeline is freed here, never in a step, once the host has read a step that
// applied the removal (no step and no snapshot it reads can reach it then) and no
// driver is still inside the port; only then is the slot taken again. The ports live
// as long as the world, so a driver that still holds one never dangles.
//
// Threads: the host; is_live and port from any thread.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/id_pool.h"
#include "hand/hand_model.h"
#include "port/hand_port.h"
#include "runtime/hand_pipeline.h"
#include "runtime/host_commands.h"
#include "runtime/world_def.h"

namespace frusta {

class HostHands {
 public:
  // sample_arrived: given to every port (HandPort)
  HostHands(const WorldDef& def, HostCommands& commands, const Wakeup* sample_arrived);

  // The world's solver settings are checked against the hand first.
  // FRUSTA_ERROR_CAPACITY when every slot is taken or still being let go of, or the
  // queue is full.
  frusta_result add(const HandModel& model, HandHandle* out);
  // FRUSTA_ERROR_STALE_ID for a handle of no hand, FRUSTA_ERROR_WRONG_STATE while a
  // device drives the hand (its port is the device's until it is closed).
  frusta_result remove(HandHandle hand);
  // Free the hands whose removal the step the host has read applied (`applied`: the
  // number of commands it had applied), and take their slots back.
  void release(uint64_t applied);

  bool is_live(HandHandle hand) const {
    return hand.generation <= 0xFFFF &&
           ids_.is_live(hand.slot, static_cast<uint16_t>(hand.generation));
  }
  // FRUSTA_ERROR_STALE_ID, with a message naming the handle, when !is_live(hand).
  frusta_result check_live(HandHandle hand) const;
  int32_t capacity() const { return static_cast<int32_t>(ports_.size()); }
  HandPort& port(int32_t slot) { return *ports_[static_cast<size_t>(slot)]; }

 private:
  WorldDef def_;
  HostCommands& commands_;
  IdPool ids_;
  std::vector<std::unique_ptr<HandPort>> ports_;           // by slot
  std::vector<std::unique_ptr<HandPipeline>> pipelines_;  // by slot
  // by slot: the number of the command removing the hand while it is let go of, else 0
  std::vector<uint64_t> removed_at_;
  uint64_t applied_ = 0;  // by the step the host read last
};

}  // namespace frusta
