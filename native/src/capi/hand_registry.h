// SPDX-License-Identifier: MIT
// Standalone hands behind frusta_hand_id: a pool of slots whose generation makes a
// destroyed hand's id stale instead of dangling.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "frusta/frusta.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"

namespace frusta {

struct HandObject {
  HandModel model;
  HandState state;
  HandPose pose;  // forward kinematics of state, refreshed on every change
};

class HandRegistry {
 public:
  frusta_result create(const frusta_hand_def& def, frusta_hand_id* out);
  frusta_result destroy(frusta_hand_id id);
  // The live hand of id in *out, or an error (null or stale id) with the message set.
  frusta_result find(frusta_hand_id id, HandObject** out);
  bool is_valid(frusta_hand_id id);

 private:
  struct Slot {
    uint16_t generation = 1;  // ids with generation 0 are never issued
    std::unique_ptr<HandObject> hand;
  };
  frusta_result find_locked(frusta_hand_id id, bool report, HandObject** out);

  std::mutex mutex_;  // create/destroy/find are rare host calls, never on a 1 kHz path
  std::vector<Slot> slots_;
  std::vector<int32_t> free_;
};

HandRegistry& hand_registry();

}  // namespace frusta
