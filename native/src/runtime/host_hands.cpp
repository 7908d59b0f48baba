// SPDX-License-Identifier: MIT
#include "runtime/host_hands.h"

#include <algorithm>

#include "core/error.h"

namespace frusta {

HostHands::HostHands(const WorldDef& def, HostCommands& commands, const Wakeup* sample_arrived)
    : def_(def),
      commands_(commands),
      ids_(def.max_hands),
      pipelines_(static_cast<size_t>(def.max_hands)),
      removed_at_(static_cast<size_t>(def.max_hands), 0) {
  for (int32_t slot = 0; slot < def.max_hands; ++slot)
    ports_.push_back(std::make_unique<HandPort>(slot, def.rate_hz, sample_arrived, def.realtime_priority));
}

frusta_result HostHands::check_live(HandHandle hand) const {
  if (!is_live(hand))
    return fail(FRUSTA_ERROR_STALE_ID, "hand {slot=%d, generation=%u} names no hand of this world",
                hand.slot, hand.generation);
  return FRUSTA_OK;
}

void HostHands::release(uint64_t applied) {
  applied_ = std::max(applied_, applied);
  for (size_t slot = 0; slot < removed_at_.size(); ++slot) {
    if (removed_at_[slot] == 0 || removed_at_[slot] > applied_ || !ports_[slot]->idle()) continue;
    pipelines_[slot].reset();
    removed_at_[slot] = 0;
    ids_.reclaim(static_cast<int32_t>(slot));
  }
}

frusta_result HostHands::add(const HandModel& model, HandHandle* out) {
  if (frusta_result r = HandSolver::check_params(def_.solver, model)) return r;
  release(applied_);  // a driver may have left a port since the last read
  int32_t slot = 0;
  uint16_t generation = 0;
  if (!ids_.acquire(&slot, &generation)) {
    const auto leaving = std::count_if(removed_at_.begin(), removed_at_.end(),
                                       [](uint64_t at) { return at != 0; });
    return fail(FRUSTA_ERROR_CAPACITY,
                "the world holds max_hands (%d) hands, %d of them removed but not yet let go "
                "of (they are once a read shows a step that applied their removal)",
                def_.max_hands, static_cast<int>(leaving));
  }
  const size_t s = static_cast<size_t>(slot);
  std::unique_ptr<HandPipeline> pipeline;
  try {
    pipeline = std::make_unique<HandPipeline>(model, def_.solver, def_.max_contacts_per_hand,
                                              def_.max_objects, slot, *ports_[s]);
  } catch (...) {
    ids_.release(slot);  // never named to anyone
    throw;
  }
  WorldCommand c;
  c.kind = CommandKind::kAddHand;
  c.slot = slot;
  c.generation = generation;
  c.hand = pipeline.get();
  // open first: the queue may be popped the moment the command is in, and the port is
  // the stepping side's from then on
  ports_[s]->open(generation);
  if (frusta_result r = commands_.push(c)) {
    ports_[s]->close();
    ids_.release(slot);
    return r;
  }
  pipelines_[s] = std::move(pipeline);
  *out = {slot, generation};
  return FRUSTA_OK;
}

frusta_result HostHands::remove(HandHandle hand) {
  if (frusta_result r = check_live(hand)) return r;
  HandPort& p = port(hand.slot);
  if (p.device_driven())
    return fail(FRUSTA_ERROR_WRONG_STATE,
                "hand {slot=%d} is driven by a glove: destroy the glove first "
                "(frusta_destroy_device)",
                hand.slot);
  WorldCommand c;
  c.kind = CommandKind::kRemoveHand;
  c.slot = hand.slot;
  if (frusta_result r = commands_.push(c)) return r;
  p.close();
  ids_.retire(hand.slot);
  removed_at_[static_cast<size_t>(hand.slot)] = commands_.pushed();
  return FRUSTA_OK;
}

}  // namespace frusta
