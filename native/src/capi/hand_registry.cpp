// SPDX-License-Identifier: MIT
#include "capi/hand_registry.h"

namespace frusta {

HandRegistry& hand_registry() {
  static HandRegistry registry;
  return registry;
}

frusta_result HandRegistry::create(const HandDef& def, frusta_hand_id* out) {
  auto hand = std::make_unique<HandObject>();
  hand->model = make_hand_model(def);
  clamp_to_limits(hand->model, hand->state);
  forward_kinematics(hand->model, hand->state, hand->pose);
  return add(std::move(hand), out);
}

}  // namespace frusta
