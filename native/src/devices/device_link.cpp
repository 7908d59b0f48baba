// SPDX-License-Identifier: MIT
#include "devices/device_link.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "core/error.h"
#include "core/periodic_clock.h"
#include "core/thread_priority.h"
#include "core/timer_resolution.h"

namespace frusta {

namespace {

constexpr int64_t kNsPerSecond = 1000000000;
constexpr int64_t kHeartbeatNs = 500000000;  // handshake retries and keep-alives
constexpr int64_t kIdleSliceNs = 10000000;   // how often a disconnected thread looks up
// woken by the step: a world that has not published this many output periods after the
// last command gets the command anyway (the watchdog's, once the engine is stalled)
constexpr int64_t kStaleCommandPeriods = 2;
int64_t to_ns(double seconds) { return static_cast<int64_t>(seconds * 1e9); }

}  // namespace

void RateMeter::add(int64_t stamp_ns, int64_t number, bool glove_clock) {
  const Entry& last = entries_[static_cast<size_t>(newest_)];
  if (count_ > 0 && (glove_clock != glove_clock_ || stamp_ns < last.stamp_ns || number <= last.number))
    count_ = 0;
  glove_clock_ = glove_clock;
  newest_ = (newest_ + 1) % kWindow;
  entries_[static_cast<size_t>(newest_)] = Entry{stamp_ns, number};
  count_ = std::min(count_ + 1, kWindow);
  const Entry& oldest = entries_[static_cast<size_t>((newest_ - count_ + 1 + kWindow) % kWindow)];
  const int64_t span = stamp_ns - oldest.stamp_ns;
  // (samples read in one burst share an arrival time: the rate waits for a span)
  if (span > 0) rate_hz_ = static_cast<double>(number - oldest.number) * 1e9 / static_cast<double>(span);
}

DeviceLink::DeviceLink(HandPort& port, const DeviceLinkDef& def, std::unique_ptr<ByteStream> stream,
                       std::unique_ptr<GloveProtocol> protocol)
    : port_(port),
      def_(def),
      stream_(std::move(stream)),
      protocol_(std::move(protocol)),
      guard_(protocol_->default_capabilities(), def.rates) {
  out_.reserve(512);
  apply_capabilities(protocol_->default_capabilities());
}

DeviceLink::~DeviceLink() { close(); }

frusta_result DeviceLink::open() {
  // the hand in the port's slot now; it stays while this holds the port (a world refuses
  // to remove a hand a device drives)
  hand_generation_ = port_.generation();
  if (hand_generation_ == 0)
    return fail(FRUSTA_ERROR_WRONG_STATE, "the port has no hand: add one to the world first");
  // one driver per hand: the port refuses a second glove, and the host while this holds it
  if (frusta_result r = port_.claim_for_device()) return r;
  if (frusta_result r = open_glove()) {
    port_.release_device();
    return r;
  }
  claimed_ = true;
  return FRUSTA_OK;
}

frusta_result DeviceLink::open_glove() {
  if (!def_.record_path.empty()) {
    if (frusta_result r = recorder_.open(def_.record_path, def_.protocol_name)) return r;
    recording_ = true;
  }
  if (frusta_result r = stream_->open()) return r;
  const int64_t now = steady_ns();
  record_start_ns_ = now;
  on_connected(now);
  publish_status(now);
  thread_ = std::thread([this] { run(); });
  return FRUSTA_OK;
}

void DeviceLink::close() {
  if (thread_.joinable()) {
    stop_.store(true, std::memory_order_release);
    thread_.join();
  }
  if (claimed_) port_.release_device();
  claimed_ = false;
}

void DeviceLink::set_palm_pose(const vec3& position, const glm::dquat& rotation) {
  PalmPose& slot = palm_.write_slot();
  slot.position = position;
  slot.rotation = rotation;
  palm_.publish();
}

const DeviceLinkStatus& DeviceLink::status() { return status_.read(); }

void DeviceLink::apply_capabilities(const DeviceCapabilities& announced) {
  DeviceCapabilities c = announced;
  c.fingers = std::clamp(c.fingers, 0, FRUSTA_FINGER_COUNT);
  c.max_finger_resistance = std::min(c.max_finger_resistance, def_.max_finger_resistance);
  c.max_fingertip_force = std::min(c.max_fingertip_force, def_.max_fingertip_force);
  c.max_joint_torque = std::min(c.max_joint_torque, def_.max_joint_torque);
  working_.capabilities = c;
  guard_.set_capabilities(c);
  const double wanted = def_.output_rate_hz > 0.0 ? def_.output_rate_hz : port_.rate_hz();
  working_.output_rate_hz = c.output_rate_hz > 0.0 ? std::min(wanted, c.output_rate_hz) : wanted;
  output_period_ns_ = static_cast<int64_t>(1e9 / working_.output_rate_hz);
}

void DeviceLink::run() {
  const FineTimerResolution fine_sleeps;
  if (port_.realtime_priority()) raise_to_realtime_priority();  // normal where refused
  uint8_t buffer[512];
  // a stream that wakes on the step's publish sends each command as soon as the step is
  // out (the sample it solved is then at most a period and a step old); others keep a
  // schedule of their own, up to a period behind the step
  const bool woken = stream_->wakes_on(&port_.feed_published());
  const int64_t world_period_ns = static_cast<int64_t>(1e9 / port_.rate_hz());
  int64_t next_output = steady_ns();
  int64_t next_reconnect = 0;
  while (!stop_.load(std::memory_order_acquire)) {
    now_ns_ = steady_ns();
    if (!stream_->is_open()) {
      if (now_ns_ >= next_reconnect) {
        if (stream_->open() == FRUSTA_OK) {
          now_ns_ = steady_ns();  // connected when the open returned, not when it began
          on_connected(now_ns_);
          next_output = now_ns_;
          continue;
        }
        next_reconnect = now_ns_ + to_ns(def_.reconnect_interval_s);
      }
      publish_status(now_ns_);
      std::this_thread::sleep_for(std::chrono::nanoseconds(
          std::clamp<int64_t>(next_reconnect - now_ns_, 0, kIdleSliceNs)));
      continue;
    }
    // due and woken: wait for the step (a stalled world's command goes out regardless,
    // kStaleCommandPeriods after the last, so the watchdog can zero it)
    int64_t until = next_output;
    if (woken && now_ns_ >= next_output) until = last_command_ns_ + kStaleCommandPeriods * output_period_ns_;
    until = std::min(until, next_heartbeat_ns_);
    size_t received = 0;
    const int64_t wait_us = std::max<int64_t>(0, until - now_ns_) / 1000;
    if (stream_->read(buffer, sizeof buffer, wait_us, &received) == IoStatus::kDisconnected) {
      on_disconnected(steady_ns());
      next_reconnect = now_ns_ + to_ns(def_.reconnect_interval_s);
      continue;
    }
    now_ns_ = steady_ns();
    if (received > 0) {
      if (recording_) recorder_.write(now_ns_ - record_start_ns_, buffer, received);
      protocol_->feed(buffer, received, this);
    }
    if (now_ns_ >= next_heartbeat_ns_ && stream_->is_open()) {
      out_.clear();
      protocol_->encode_heartbeat(&out_);
      write_bytes(false);
      next_heartbeat_ns_ = now_ns_ + kHeartbeatNs;
    }
    if (now_ns_ < next_output || !stream_->is_open()) continue;
    const DeviceFeed& feed = port_.read_feed();
    const bool fresh = feed.step != sent_step_;
    if (woken && !fresh && now_ns_ < last_command_ns_ + kStaleCommandPeriods * output_period_ns_)
      continue;
    send_command(now_ns_, feed);
    if (woken && !fresh) {
      next_output = now_ns_;  // the step is late: its command goes the moment it is out
    } else if (woken) {
      // paced by the steps: the first publish an output period on, whenever it comes
      // (half a world period early is still the one due)
      next_output = now_ns_ + std::max(output_period_ns_ / 2, output_period_ns_ - world_period_ns / 2);
    } else {
      next_output += output_period_ns_;
      if (next_output <= now_ns_) next_output = now_ns_ + output_period_ns_;  // fell behind
    }
    publish_status(now_ns_);
  }
  // leaving: the glove's last command releases it
  if (stream_->is_open()) {
    out_.clear();
    protocol_->encode(guard_.zero(), working_.capabilities, &out_);
    write_bytes(true);
    stream_->close();
  }
  working_.state = LinkState::kClosed;
  publish_status(steady_ns());
}

void DeviceLink::on_connected(int64_t now) {
  if (ever_connected_) ++working_.reconnects;
  ever_connected_ = true;
  working_.state = LinkState::kConnected;
  last_sample_ns_ = 0;  // zeros until the glove speaks again
  input_rate_.reset();
  samples_taken_ = 0;
  last_command_ns_ = now;
  guard_.zero();
  out_.clear();
  protocol_->start(&out_);
  write_bytes(false);
  next_heartbeat_ns_ = now + kHeartbeatNs;
}

void DeviceLink::on_disconnected(int64_t now) {
  stream_->close();
  if (working_.watchdog == WatchdogReason::kNone) ++working_.watchdog_trips;
  working_.watchdog = WatchdogReason::kDisconnected;
  working_.state = LinkState::kDisconnected;
  ++working_.disconnects;
  guard_.zero();
  publish_status(now);
}

WatchdogReason DeviceLink::check_watchdog(int64_t now, const DeviceFeed& feed) const {
  if (last_sample_ns_ == 0 || now - last_sample_ns_ > to_ns(def_.watchdog_s))
    return WatchdogReason::kInputStalled;
  if (feed.step == 0 || now - feed.published_ns > to_ns(def_.engine_timeout_s))
    return WatchdogReason::kEngineStalled;
  if (def_.host_timeout_s > 0.0 &&
      (feed.host_read_ns == 0 || now - feed.host_read_ns > to_ns(def_.host_timeout_s)))
    return WatchdogReason::kHostStalled;
  return WatchdogReason::kNone;
}

void DeviceLink::send_command(int64_t now, const DeviceFeed& feed) {
  const WatchdogReason reason = check_watchdog(now, feed);
  if (reason != WatchdogReason::kNone) {
    if (working_.watchdog == WatchdogReason::kNone) ++working_.watchdog_trips;
    guard_.zero();
  } else {
    const double dt = std::min(static_cast<double>(now - last_command_ns_) / 1e9, 0.1);
    guard_.shape(feed.device, feed.haptic_palm_rotation, dt);
  }
  working_.watchdog = reason;
  last_command_ns_ = now;
  sent_step_ = feed.step;
  out_.clear();
  protocol_->encode(guard_.last(), working_.capabilities, &out_);
  write_bytes(true);
  // the first command to answer a sample of this glove's (the input number restarts
  // with each hand the port is opened to: a lower one is a new hand's)
  if (feed.input_sequence != answered_input_ && feed.input_set_ns > 0 && !out_.empty()) {
    answered_input_ = feed.input_sequence;
    const int64_t written = steady_ns();
    working_.sample_to_step.record(static_cast<double>(feed.published_ns - feed.input_set_ns) / 1e3);
    working_.step_to_command.record(static_cast<double>(written - feed.published_ns) / 1e3);
    working_.sample_to_command.record(static_cast<double>(written - feed.input_set_ns) / 1e3);
  }
}

void DeviceLink::write_bytes(bool command) {
  if (out_.empty()) return;
  bool dropped = false;
  if (stream_->write(out_.data(), out_.size(), &dropped) == IoStatus::kDisconnected) {
    on_disconnected(steady_ns());
    return;
  }
  if (!command) return;
  if (dropped)
    ++working_.commands_dropped;
  else
    ++working_.commands_sent;
}

void DeviceLink::publish_status(int64_t now) {
  working_.last_sample_age_s =
      last_sample_ns_ == 0 ? -1.0 : static_cast<double>(now - last_sample_ns_) / 1e9;
  working_.last_command = guard_.last();
  working_.recording_failed = recorder_.failed();
  status_.write_slot() = working_;
  status_.publish();
}

void DeviceLink::on_sample(const DeviceSample& sample) {
  HandState haptic = haptic_;
  haptic.angles = sample.angles;
  if (sample.has_palm_pose) {
    haptic.palm_position = sample.palm_position;
    haptic.palm_rotation = sample.palm_rotation;
  } else {
    const PalmPose& palm = palm_.read();
    haptic.palm_position = palm.position;
    haptic.palm_rotation = palm.rotation;
  }
  // the one rule for a hand's inputs, checked where the port takes them
  if (port_.set_input(haptic, HandPort::Driver::kDevice, hand_generation_) != FRUSTA_OK) {
    ++working_.samples_rejected;
    return;
  }
  haptic_ = haptic;
  ++working_.frames_ok;
  // by the glove's clock and count when it sends both (a clock past 292 years in ns is
  // a broken glove's: arrival and our count are used instead)
  ++samples_taken_;
  const bool glove_clock = sample.device_time_us >= 0 && sample.device_time_us <= INT64_MAX / 1000 &&
                           sample.sequence >= 0;
  input_rate_.add(glove_clock ? sample.device_time_us * 1000 : now_ns_,
                  glove_clock ? sample.sequence : samples_taken_, glove_clock);
  if (input_rate_.rate_hz() > 0.0) working_.input_rate_hz = input_rate_.rate_hz();
  last_sample_ns_ = now_ns_;
}

void DeviceLink::on_capabilities(const DeviceCapabilities& capabilities) {
  apply_capabilities(capabilities);
}

void DeviceLink::on_fault(FrameFault fault) {
  switch (fault) {
    case FrameFault::kCorrupt: ++working_.frames_corrupt; break;
    case FrameFault::kTruncated: ++working_.frames_truncated; break;
    case FrameFault::kOutOfRange: ++working_.frames_out_of_range; break;
  }
}

void DeviceLink::on_heartbeat() {}

}  // namespace frusta
