// SPDX-License-Identifier: MIT
#include "capi/hand_registry.h"

#include "core/error.h"

namespace frusta {

namespace {
// slots are int32 indices + 1 in ids; far more hands than any scene needs
constexpr size_t kMaxHands = 1 << 16;
}  // namespace

HandRegistry& hand_registry() {
  static HandRegistry registry;
  return registry;
}

frusta_result HandRegistry::create(const frusta_hand_def& def, frusta_hand_id* out) {
  auto hand = std::make_unique<HandObject>();
  hand->model = make_hand_model(def);
  clamp_to_limits(hand->model, hand->state);
  forward_kinematics(hand->model, hand->state, hand->pose);

  std::lock_guard<std::mutex> lock(mutex_);
  int32_t index;
  if (!free_.empty()) {
    index = free_.back();
    free_.pop_back();
  } else {
    if (slots_.size() >= kMaxHands)
      return fail(FRUSTA_ERROR_CAPACITY, "too many hands alive (%zu)", kMaxHands);
    index = static_cast<int32_t>(slots_.size());
    slots_.emplace_back();
  }
  Slot& slot = slots_[static_cast<size_t>(index)];
  slot.hand = std::move(hand);
  *out = frusta_hand_id{index + 1, 0, slot.generation};
  return FRUSTA_OK;
}

frusta_result HandRegistry::destroy(frusta_hand_id id) {
  std::lock_guard<std::mutex> lock(mutex_);
  HandObject* hand = nullptr;
  if (frusta_result r = find_locked(id, true, &hand)) return r;
  Slot& slot = slots_[static_cast<size_t>(id.index1 - 1)];
  slot.hand.reset();
  // skip 0 on wrap-around so a zero-initialised id never matches
  slot.generation = static_cast<uint16_t>(slot.generation == UINT16_MAX ? 1 : slot.generation + 1);
  free_.push_back(id.index1 - 1);
  return FRUSTA_OK;
}

frusta_result HandRegistry::find(frusta_hand_id id, HandObject** out) {
  std::lock_guard<std::mutex> lock(mutex_);
  return find_locked(id, true, out);
}

bool HandRegistry::is_valid(frusta_hand_id id) {
  std::lock_guard<std::mutex> lock(mutex_);
  HandObject* hand = nullptr;
  return find_locked(id, false, &hand) == FRUSTA_OK;
}

frusta_result HandRegistry::find_locked(frusta_hand_id id, bool report, HandObject** out) {
  if (FRUSTA_IS_NULL(id)) {
    return report ? fail(FRUSTA_ERROR_NULL_ID, "hand id is null (zero-initialised)")
                  : FRUSTA_ERROR_NULL_ID;
  }
  const size_t index = static_cast<size_t>(id.index1) - 1;
  if (id.index1 < 0 || index >= slots_.size() || id.world0 != 0 ||
      slots_[index].generation != id.generation || !slots_[index].hand) {
    return report ? fail(FRUSTA_ERROR_STALE_ID, "hand id {index1=%d, world0=%u, generation=%u} "
                         "names no live hand: it was destroyed or never created",
                         id.index1, id.world0, id.generation)
                  : FRUSTA_ERROR_STALE_ID;
  }
  *out = slots_[index].hand.get();
  return FRUSTA_OK;
}

}  // namespace frusta
