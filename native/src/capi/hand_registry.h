// SPDX-License-Identifier: MIT
// Standalone hands behind frusta_hand_id.
#pragma once

#include "capi/registry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"

namespace frusta {

struct HandObject {
  HandModel model;
  HandState state;
  HandPose pose;  // forward kinematics of state, refreshed on every change
};

class HandRegistry : public Registry<HandObject, frusta_hand_id> {
 public:
  HandRegistry() : Registry("hand") {}
  // Build a hand from a checked def, at rest (angles clamped into the limits).
  frusta_result create(const HandDef& def, frusta_hand_id* out);
};

HandRegistry& hand_registry();

}  // namespace frusta
