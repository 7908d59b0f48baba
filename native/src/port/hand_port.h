// SPDX-License-Identifier: MIT
// The seam between one hand of a world and what drives it: the host (through
// frusta_world_set_haptic) or a glove's thread. The world owns one port per hand slot,
// for as long as it lives, so a driver holding one never dangles; the port is opened
// to each hand that takes the slot and closed when the hand goes. A driver writes the
// hand's haptic input to the port and reads the hand's device feed from it; it never
// sees the world. One driver at a time: a glove claims the port, and while it holds it
// the host's inputs are refused.
//
// Threads: set_input and set_input_at from any one thread per port (its driver; a
// driver of a hand already gone may still be in it); read_feed from one device thread; open / close /
// idle / claim_for_device / release_device from the host; the stepping thread takes
// the input and publishes the feed. No call waits for another.
#pragma once

#include <atomic>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>

#include "core/base.h"
#include "core/spsc_queue.h"
#include "core/triple_buffer.h"
#include "core/wakeup.h"
#include "forces/device_outputs.h"
#include "hand/kinematics.h"

namespace frusta {

// A haptic input, when it was set (steady clock, ns) and the time it is for: its
// driver's stamp on the world's clock (timed), or else when it was set. Inputs do not
// arrive one per step, and a host that stalls delivers them late and in bursts; the
// world plays them by their times, a fixed delay behind (runtime/input_playback.h).
struct TimedInput {
  HandState state;  // checked by check_hand_state, rotation unit
  int64_t set_ns = 0;
  int64_t time_ns = 0;    // the sample's time: the driver's (timed) or set_ns
  uint64_t sequence = 0;  // 1, 2, ... per hand in the port: the order they were set
  bool timed = false;     // the driver stamped it (set_input_at)
  // a glove's unstamped sample: the step solves the newest as it is, with no jitter
  // buffer's delay (a glove's thread reads its samples as they come, about one a
  // period, and every period of delay is felt in the hand)
  bool live = false;
};

// What a device thread reads at its own rate: its hand's device outputs and whether
// the world and its host are alive, apart from the host's snapshot.
struct DeviceFeed {
  uint64_t step = 0;          // 0 until the first step
  int64_t published_ns = 0;   // steady clock, when the step published it
  int64_t host_read_ns = 0;   // steady clock, the host's last snapshot read (0: never)
  bool solved = false;        // false until the hand's first valid haptic input
  DeviceOutputs device;       // clamped to the world's device limits; world frame
  glm::dquat haptic_palm_rotation{1.0, 0.0, 0.0, 0.0};  // of the input the step used
  // the newest input the step had: its number (TimedInput::sequence, 0: none) and when
  // it was set (steady clock, ns), so a device can tell which sample a command answers
  uint64_t input_sequence = 0;
  int64_t input_set_ns = 0;
};

class HandPort {
 public:
  enum class Driver : uint8_t { kHost, kDevice };

  // hand: the hand slot in its world (for messages); rate_hz: the world's step rate,
  // which a device paces its commands by; sample_arrived (may be null, must outlive the
  // port): signalled as a device sets a live sample, so the world's thread answers it at
  // once; realtime_priority: the world's wish for its devices' threads. Closed until
  // open().
  HandPort(int32_t hand, double rate_hz, const Wakeup* sample_arrived = nullptr,
           bool realtime_priority = false);
  HandPort(const HandPort&) = delete;
  HandPort& operator=(const HandPort&) = delete;

  // Host: give the port to the hand whose ids carry `generation` (not 0), with no input
  // and no feed yet. Only while nothing else uses the port: closed, idle(), and no step
  // solving a hand through it.
  void open(uint32_t generation);
  // Host: the hand goes; inputs naming it are refused from now on.
  void close();
  // Host: whether no driver is inside set_input (one of a hand just closed may be).
  bool idle() const { return writers_.load(std::memory_order_seq_cst) == 0; }
  // The open hand's generation; 0 when closed.
  uint32_t generation() const { return generation_.load(std::memory_order_acquire); }

  // The driver of the hand `generation` names: the newest input, which the world's next
  // step uses. FRUSTA_ERROR_STALE_ID when that hand is no longer the port's. The one
  // rule for a hand's inputs (check_hand_state) is checked here, and what passes is
  // used; the host (kHost) is refused with FRUSTA_ERROR_WRONG_STATE while a device
  // drives the hand.
  frusta_result set_input(const HandState& state, Driver from, uint32_t generation);
  // The same, for a sample the driver stamped with its time on the world's clock (ns):
  // each hand's timed samples must come in time order (FRUSTA_ERROR_OUT_OF_RANGE for one
  // no later than the one before). Every sample is kept for the step, up to
  // kInputQueueCapacity between two steps (beyond that, the newest still reaches it).
  frusta_result set_input_at(const HandState& state, int64_t time_ns, Driver from,
                             uint32_t generation);
  // One device thread: the newest feed, unchanged until its next call.
  const DeviceFeed& read_feed() { return feed_.read(); }
  double rate_hz() const { return rate_hz_; }
  // whether a device's thread should ask for real-time priority (WorldDef)
  bool realtime_priority() const { return realtime_priority_; }

  // Host: a device takes the hand (FRUSTA_ERROR_WRONG_STATE if one has it already), or
  // gives it back to the host.
  frusta_result claim_for_device();
  void release_device();
  bool device_driven() const { return device_.load(std::memory_order_acquire); }
  // Signalled by publish_feed while a device drives the hand (opened by its first
  // claim): its thread sends the command that answers a step as soon as it is out.
  const Wakeup& feed_published() const { return feed_published_; }

  // The stepping thread: whether an input came since the last take, and the newest.
  bool input_fresh() const { return input_.fresh(); }
  const TimedInput& take_input() { return input_.read(); }
  // The stepping thread: the inputs in the order they were set, oldest first; false
  // when none is waiting. A burst larger than the queue loses its middle: the newest
  // is still take_input()'s.
  bool pop_input(TimedInput& out) { return queue_.pop(out); }
  static constexpr size_t kInputQueueCapacity = 64;
  // The stepping thread: publish the hand's feed for its device.
  void publish_feed(const DeviceFeed& feed);

 private:
  // set_input(_at) once the driver is counted in and the hand is the port's; time_ns < 0:
  // untimed
  frusta_result write_input(const HandState& state, int64_t time_ns, Driver from);
  frusta_result enter(uint32_t generation);

  TripleBuffer<TimedInput> input_;  // the newest
  SpscQueue<TimedInput> queue_{kInputQueueCapacity};  // every one, in order
  // the driver's (one at a time; atomic as drivers change hands): the last sequence
  // number and the last timed sample's time
  std::atomic<uint64_t> sequence_{0};
  std::atomic<int64_t> last_time_ns_{INT64_MIN};
  TripleBuffer<DeviceFeed> feed_;
  Wakeup feed_published_;  // opened before device_ is first set; never closed
  const Wakeup* sample_arrived_;
  std::atomic<bool> device_{false};
  // a driver counts itself in, then checks the generation; the host closes, then checks
  // the count (both sequentially consistent): either the driver sees the port closed,
  // or the host sees the driver in, and keeps the port until it has left
  std::atomic<uint32_t> generation_{0};
  std::atomic<int32_t> writers_{0};
  int32_t hand_;
  double rate_hz_;
  bool realtime_priority_;
};

}  // namespace frusta
