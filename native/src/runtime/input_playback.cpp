// SPDX-License-Identifier: MIT
#include "runtime/input_playback.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace frusta {

bool InputPlayback::push(const TimedInput& input) {
  if (count_ > 0) {
    TimedInput& last = ring_[(head_ + count_ - 1) % kCapacity];
    // the queue and the newest-value buffer may both bring the same sample
    if (input.sequence <= last.sequence) return false;
    if (input.timed != last.timed) {
      // a driver that switches between stamped and unstamped samples starts over: the
      // two are on different clocks when the host steps
      count_ = 0;
      has_played_ = rejoining_ = false;
    } else if (input.time_ns <= last.time_ns) {
      // unstamped samples set within one tick of the clock: the newer stands for both
      last = input;
      return true;
    }
  }
  if (count_ == kCapacity) drop_oldest();
  ring_[(head_ + count_) % kCapacity] = input;
  ++count_;
  return true;
}

void InputPlayback::drop_oldest() {
  head_ = (head_ + 1) % kCapacity;
  --count_;
}

void InputPlayback::keep_newest() {
  while (count_ > 1) drop_oldest();
}

namespace {

// whether two inputs differ by more than rounding
bool differs(const HandState& a, const HandState& b) {
  if (glm::length(a.palm_position - b.palm_position) > 1e-12) return true;
  if (std::fabs(glm::dot(a.palm_rotation, b.palm_rotation)) < 1.0 - 1e-15) return true;
  for (size_t j = 0; j < a.angles.size(); ++j)
    if (std::fabs(a.angles[j] - b.angles[j]) > 1e-12) return true;
  return false;
}

}  // namespace

HandState InputPlayback::play(int64_t at_ns, int64_t max_extrapolation_ns, bool* late) {
  const int64_t newest_ns = newest().time_ns;
  *late = at_ns > newest_ns;
  const bool stopped = at_ns - newest_ns > max_extrapolation_ns + kStopNs;
  if (has_played_ && at_ns > played_ns_) {
    // what the samples now say of the time played last, by the rule of this step's own
    // answer (held at the newest once the stream has stopped): another answer than then
    // (late samples came, or the stream has stopped) is a jump, which fades out from
    // there. Judged by the time played last instead, a stream lagging just past the stop
    // made every new sample a jump of max_extrapolation's worth, and the fades piled up.
    const HandState then = sampled(played_ns_, max_extrapolation_ns, stopped);
    if (differs(then, played_raw_)) {
      offset_position_ = played_.palm_position - then.palm_position;
      offset_rotation_ = played_.palm_rotation * glm::conjugate(then.palm_rotation);
      if (offset_rotation_.w < 0.0) offset_rotation_ = -offset_rotation_;
      for (size_t j = 0; j < offset_angles_.size(); ++j)
        offset_angles_[j] = played_.angles[j] - then.angles[j];
      offset_ns_ = played_ns_;
      rejoining_ = true;
    }
  }
  // what is older than the sample before at_ns no step needs again, but for the
  // newest's velocity window
  size_t i = 0;
  while (i + 1 < count_ && at(i + 1).time_ns <= at_ns) ++i;
  while (i > 0 && newest_ns - at(1).time_ns >= kVelocityWindowNs) {
    drop_oldest();
    --i;
  }
  const HandState raw = sampled(at_ns, max_extrapolation_ns, stopped);
  HandState out = raw;
  if (rejoining_) {
    const double left = 1.0 - static_cast<double>(at_ns - offset_ns_) / static_cast<double>(kRejoinNs);
    if (left <= 0.0) {
      rejoining_ = false;
    } else {
      out.palm_position += left * offset_position_;
      out.palm_rotation = glm::normalize(
          glm::slerp(glm::dquat(1.0, 0.0, 0.0, 0.0), offset_rotation_, left) * out.palm_rotation);
      for (size_t j = 0; j < out.angles.size(); ++j) out.angles[j] += left * offset_angles_[j];
    }
  }
  played_ = out;
  played_raw_ = raw;
  played_ns_ = at_ns;
  has_played_ = true;
  return out;
}

HandState InputPlayback::sampled(int64_t at_ns, int64_t max_extrapolation_ns, bool stopped) const {
  size_t i = 0;
  while (i + 1 < count_ && at(i + 1).time_ns <= at_ns) ++i;
  const TimedInput& a = at(i);
  if (at_ns <= a.time_ns) return a.state;  // before the oldest (or on a sample)
  if (i + 1 < count_) {
    const TimedInput& b = at(i + 1);
    const double t = static_cast<double>(at_ns - a.time_ns) / static_cast<double>(b.time_ns - a.time_ns);
    return interpolate(a.state, b.state, t);
  }
  // past the newest: from its velocity over the window, for a bounded time, held there
  // until the stream has stopped, then the newest. Only samples their driver stamped:
  // the times of unstamped ones are when they arrived, which a burst squeezes together
  const int64_t newest_ns = a.time_ns;
  if (count_ < 2 || !a.timed || max_extrapolation_ns <= 0 || stopped) return a.state;
  size_t r = count_ - 2;
  while (r > 0 && newest_ns - at(r).time_ns < kVelocityWindowNs) --r;
  const TimedInput& from = at(r);
  return extrapolate(from.state, a.state, newest_ns - from.time_ns,
                     std::min(at_ns - newest_ns, max_extrapolation_ns));
}

HandState extrapolate(const HandState& from, const HandState& to, int64_t span_ns,
                      int64_t ahead_ns) {
  const double s = static_cast<double>(ahead_ns) / static_cast<double>(span_ns);
  HandState out = to;
  out.palm_position = to.palm_position + s * (to.palm_position - from.palm_position);
  for (size_t j = 0; j < out.angles.size(); ++j)
    out.angles[j] = to.angles[j] + s * (to.angles[j] - from.angles[j]);
  // the turn from `from` to `to`, along the shorter arc, continued s times as far
  glm::dquat turn = to.palm_rotation * glm::conjugate(from.palm_rotation);
  if (turn.w < 0.0) turn = -turn;
  const double half = std::acos(std::clamp(turn.w, -1.0, 1.0));
  const double sin_half = std::sin(half);
  if (sin_half > 1e-12) {
    const vec3 axis = vec3(turn.x, turn.y, turn.z) / sin_half;
    out.palm_rotation = glm::normalize(glm::angleAxis(2.0 * half * s, axis) * to.palm_rotation);
  }
  return out;
}

}  // namespace frusta
