// SPDX-License-Identifier: MIT
#include "port/hand_port.h"

#include "core/error.h"
#include "core/periodic_clock.h"

namespace frusta {

HandPort::HandPort(int32_t hand, double rate_hz)
    : input_(TimedInput{}), feed_(DeviceFeed{}), hand_(hand), rate_hz_(rate_hz) {}

void HandPort::open(uint32_t generation) {
  input_.reset(TimedInput{});
  feed_.reset(DeviceFeed{});
  generation_.store(generation, std::memory_order_seq_cst);
}

void HandPort::close() { generation_.store(0, std::memory_order_seq_cst); }

frusta_result HandPort::set_input(const HandState& state, Driver from, uint32_t generation) {
  writers_.fetch_add(1, std::memory_order_seq_cst);
  if (generation == 0 || generation_.load(std::memory_order_seq_cst) != generation) {
    writers_.fetch_sub(1, std::memory_order_release);  // out before the message is written
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand {slot=%d, generation=%u} names no hand of this world: it was destroyed, or "
                "never added",
                hand_, generation);
  }
  const frusta_result r = write_input(state, from);
  writers_.fetch_sub(1, std::memory_order_release);
  return r;
}

frusta_result HandPort::write_input(const HandState& state, Driver from) {
  if (from == Driver::kHost && device_driven())
    return fail(FRUSTA_ERROR_WRONG_STATE,
                "hand %d is driven by a glove: set its palm through the glove "
                "(frusta_device_set_palm_pose), or close the glove first", hand_);
  // refused here or never: an input taken is an input the step uses
  if (frusta_result r = check_hand_state(state, "haptic")) return r;
  TimedInput& slot = input_.write_slot();
  slot.state = state;
  // unit from here on: inputs are interpolated, and slerp assumes unit quaternions
  slot.state.palm_rotation = glm::normalize(state.palm_rotation);
  slot.set_ns = steady_ns();
  input_.publish();
  return FRUSTA_OK;
}

frusta_result HandPort::claim_for_device() {
  bool expected = false;
  if (!device_.compare_exchange_strong(expected, true, std::memory_order_acq_rel))
    return fail(FRUSTA_ERROR_WRONG_STATE, "hand %d already has a glove: close it first", hand_);
  return FRUSTA_OK;
}

void HandPort::release_device() { device_.store(false, std::memory_order_release); }

void HandPort::publish_feed(const DeviceFeed& feed) {
  feed_.write_slot() = feed;
  feed_.publish();
}

}  // namespace frusta
