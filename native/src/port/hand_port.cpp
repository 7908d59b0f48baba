// SPDX-License-Identifier: MIT
#include "port/hand_port.h"

#include "core/error.h"
#include "core/periodic_clock.h"

namespace frusta {

HandPort::HandPort(int32_t hand, double rate_hz, const Wakeup* sample_arrived, bool realtime_priority)
    : input_(TimedInput{}),
      feed_(DeviceFeed{}),
      sample_arrived_(sample_arrived),
      hand_(hand),
      rate_hz_(rate_hz),
      realtime_priority_(realtime_priority) {}

void HandPort::open(uint32_t generation) {
  input_.reset(TimedInput{});
  TimedInput stale;
  while (queue_.pop(stale)) {
  }  // what the hand before this one was sent and never took
  sequence_.store(0, std::memory_order_relaxed);
  last_time_ns_.store(INT64_MIN, std::memory_order_relaxed);
  feed_.reset(DeviceFeed{});
  generation_.store(generation, std::memory_order_seq_cst);
}

void HandPort::close() { generation_.store(0, std::memory_order_seq_cst); }

frusta_result HandPort::enter(uint32_t generation) {
  writers_.fetch_add(1, std::memory_order_seq_cst);
  if (generation == 0 || generation_.load(std::memory_order_seq_cst) != generation) {
    writers_.fetch_sub(1, std::memory_order_release);  // out before the message is written
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand {slot=%d, generation=%u} names no hand of this world: it was destroyed, or "
                "never added",
                hand_, generation);
  }
  return FRUSTA_OK;
}

frusta_result HandPort::set_input(const HandState& state, Driver from, uint32_t generation) {
  if (frusta_result r = enter(generation)) return r;
  const frusta_result r = write_input(state, -1, from);
  writers_.fetch_sub(1, std::memory_order_release);
  return r;
}

frusta_result HandPort::set_input_at(const HandState& state, int64_t time_ns, Driver from,
                                     uint32_t generation) {
  if (frusta_result r = enter(generation)) return r;
  const frusta_result r = write_input(state, time_ns, from);
  writers_.fetch_sub(1, std::memory_order_release);
  return r;
}

frusta_result HandPort::write_input(const HandState& state, int64_t time_ns, Driver from) {
  if (from == Driver::kHost && device_driven())
    return fail(FRUSTA_ERROR_WRONG_STATE,
                "hand %d is driven by a glove: set its palm through the glove "
                "(frusta_device_set_palm_pose), or close the glove first", hand_);
  // refused here or never: an input taken is an input the step uses
  if (frusta_result r = check_hand_state(state, "haptic")) return r;
  const bool timed = time_ns >= 0;
  if (timed) {
    const int64_t last = last_time_ns_.load(std::memory_order_relaxed);
    if (time_ns <= last)
      return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                  "time is %.9f s, no later than the hand's previous sample (%.9f s): a hand's "
                  "samples must come in time order",
                  static_cast<double>(time_ns) * 1e-9, static_cast<double>(last) * 1e-9);
    last_time_ns_.store(time_ns, std::memory_order_relaxed);
  }
  TimedInput& slot = input_.write_slot();
  slot.state = state;
  // unit from here on: inputs are interpolated, and slerp assumes unit quaternions
  slot.state.palm_rotation = glm::normalize(state.palm_rotation);
  slot.set_ns = steady_ns();
  slot.time_ns = timed ? time_ns : slot.set_ns;
  slot.timed = timed;
  slot.live = !timed && from == Driver::kDevice;
  slot.sequence = sequence_.fetch_add(1, std::memory_order_relaxed) + 1;
  // every sample in order for the step's playback; when a burst fills the queue, the
  // newest still reaches the step through the triple buffer
  queue_.push(slot);
  const bool live = slot.live;
  input_.publish();
  if (live && sample_arrived_ != nullptr) sample_arrived_->signal();
  return FRUSTA_OK;
}

frusta_result HandPort::claim_for_device() {
  // before device_ says a device drives the hand (the step signals only then); without
  // one the device keeps its own schedule
  feed_published_.open();
  bool expected = false;
  if (!device_.compare_exchange_strong(expected, true, std::memory_order_acq_rel))
    return fail(FRUSTA_ERROR_WRONG_STATE, "hand %d already has a glove: close it first", hand_);
  return FRUSTA_OK;
}

void HandPort::release_device() { device_.store(false, std::memory_order_release); }

void HandPort::publish_feed(const DeviceFeed& feed) {
  feed_.write_slot() = feed;
  feed_.publish();
  // one non-blocking write: the device thread answers this step now, not on its own
  // schedule up to a period later
  if (device_driven()) feed_published_.signal();
}

}  // namespace frusta
