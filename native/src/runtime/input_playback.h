// SPDX-License-Identifier: MIT
// A hand's jitter buffer: the samples its driver delivered, played at a fixed delay
// behind the step's time. A host that stalls and then catches up delivers its samples
// late and squeezed together; played by their own times they are the motion the user
// made, not the host's hiccups. Between two samples the input is interpolated (palm
// straight, its rotation along the shorter arc, angles straight); past the newest it
// is extrapolated from the newest's velocity for at most max_extrapolation, then held
// there (samples their driver stamped only: an unstamped sample's time is when it
// arrived, which a burst squeezes, so past the newest of those the hand holds); a
// stream silent kStopNs longer has stopped, and the hand goes back to its newest
// sample. Whenever the answer jumps (late samples came at last, the stream
// stopped), the hand fades from what it played to the new answer over kRejoinNs
// instead of jumping: a held object's stick springs let go at a fraction of a
// millimetre's jerk.
//
// Threads: the stepping thread (the constructor: the host's, when the hand is added).
// A fixed ring sized at construction; nothing is allocated afterwards.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hand/kinematics.h"
#include "port/hand_port.h"

namespace frusta {

class InputPlayback {
 public:
  // samples kept: a hand at 1 kHz needs a delay's and a velocity window's worth
  static constexpr size_t kCapacity = 256;
  // the newest's velocity is taken over at least this long (ns) when the samples
  // reach that far back, so the noise of their times is not magnified
  static constexpr int64_t kVelocityWindowNs = 5'000'000;
  // how long the hand takes to rejoin its samples after playing past them
  static constexpr int64_t kRejoinNs = 20'000'000;
  // silent this long past max_extrapolation, a stream has stopped
  static constexpr int64_t kStopNs = 100'000'000;

  InputPlayback() : ring_(kCapacity) {}

  // Adds a sample after the ones there: one set before the newest is dropped, one of
  // the newest's time replaces it, one of the other kind (timed or not) starts over,
  // and the oldest is let go of when the ring is full.
  bool push(const TimedInput& input);
  bool empty() const { return count_ == 0; }
  size_t size() const { return count_; }
  const TimedInput& newest() const { return at(count_ - 1); }
  // Only the newest is kept (the host takes it as it is, and plays nothing older).
  void keep_newest();

  // The input at time `at_ns` (not empty): before the oldest sample, the oldest;
  // between two samples, interpolated; past the newest, extrapolated by at most
  // max_extrapolation_ns from the newest's velocity and held there, and the newest once
  // the stream has stopped; a jump in that answer fades out over kRejoinNs. *late:
  // whether at_ns is past the newest sample. Samples older than needed are let go of.
  HandState play(int64_t at_ns, int64_t max_extrapolation_ns, bool* late);

 private:
  const TimedInput& at(size_t i) const { return ring_[(head_ + i) % kCapacity]; }
  void drop_oldest();
  // the samples' input at at_ns, as play() says, without the rejoin; past the newest,
  // the newest where the stream has `stopped` (judged at the step's time)
  HandState sampled(int64_t at_ns, int64_t max_extrapolation_ns, bool stopped) const;

  // the rejoin: the last played input, the samples' answer for it and its time, and
  // the offset fading out since offset_ns
  HandState played_, played_raw_;
  int64_t played_ns_ = 0;
  bool has_played_ = false, rejoining_ = false;
  vec3 offset_position_{0.0};
  glm::dquat offset_rotation_{1.0, 0.0, 0.0, 0.0};
  std::array<double, FRUSTA_HAND_JOINT_COUNT> offset_angles_{};
  int64_t offset_ns_ = 0;

  std::vector<TimedInput> ring_;
  size_t head_ = 0, count_ = 0;
};

// `from` moved on past `to` as it moved from `from` to `to` over span_ns, for another
// ahead_ns: palm straight, its rotation about the same axis at the same rate, angles
// straight (clamped to the hand's limits by the solver).
HandState extrapolate(const HandState& from, const HandState& to, int64_t span_ns,
                      int64_t ahead_ns);

}  // namespace frusta
