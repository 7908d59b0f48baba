// SPDX-License-Identifier: MIT
// One glove driving one hand, through the hand's port (port/hand_port.h), on a thread
// of its own that exists only while the glove is open. Each turn of the thread reads
// what the glove sent (samples go to the port's lock-free input, as a host's would)
// and, at the output rate, sends the glove its command from the port's device feed,
// through the output guard. It never waits on the world or the host, and sees
// neither.
//
// Safety: the command drops to zero, at once, when no valid sample came for the
// watchdog period, when the world has published no step for the engine timeout, when
// the host has read no snapshot for the host timeout, or when the glove disconnects.
// The glove is reopened every reconnect interval; after a reconnect the glove gets
// zeros until its first valid sample, so it resumes from where the hand is now.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "core/triple_buffer.h"
#include "devices/byte_stream.h"
#include "devices/device_types.h"
#include "devices/glove_protocol.h"
#include "devices/output_guard.h"
#include "devices/recording.h"
#include "port/hand_port.h"
#include "core/step_histogram.h"

namespace frusta {

// Samples per second over the last kWindow samples, from their stamps and numbers: the
// glove's own clock and count where its samples carry them (the binary profile's), so
// neither a loaded host that reads them late and in bursts nor a sample lost on the way
// moves the figure; else their arrival, numbered as taken. A stamp or number that goes
// back (the glove restarted) starts the window over.
class RateMeter {
 public:
  static constexpr int kWindow = 64;
  void reset() { count_ = 0; }
  void add(int64_t stamp_ns, int64_t number, bool glove_clock);
  double rate_hz() const { return rate_hz_; }  // 0 until two stamps apart

 private:
  struct Entry {
    int64_t stamp_ns, number;
  };
  std::array<Entry, kWindow> entries_{};  // a ring: the newest at newest_
  int count_ = 0, newest_ = 0;
  bool glove_clock_ = false;
  double rate_hz_ = 0.0;
};

struct DeviceLinkDef {
  double output_rate_hz = 0.0;  // 0: the world's rate; never above the glove's
  double watchdog_s = 0.05;
  double engine_timeout_s = 0.05;
  double host_timeout_s = 0.25;  // 0: the host's reading is not watched
  double reconnect_interval_s = 0.2;
  OutputRates rates;
  // the glove's limits, under which its announced ones are taken (the lower wins)
  double max_finger_resistance = 10.0;
  double max_fingertip_force = 10.0;
  double max_joint_torque = 0.5;
  std::string record_path;  // empty: no recording
  std::string protocol_name;  // written into the recording
};

enum class LinkState : int32_t { kConnected = 1, kDisconnected = 2, kClosed = 3 };
enum class WatchdogReason : int32_t {
  kNone = 0,
  kInputStalled = 1,
  kDisconnected = 2,
  kEngineStalled = 3,
  kHostStalled = 4,
};

struct DeviceLinkStatus {
  LinkState state = LinkState::kDisconnected;
  WatchdogReason watchdog = WatchdogReason::kNone;
  int64_t frames_ok = 0, frames_corrupt = 0, frames_truncated = 0, frames_out_of_range = 0;
  int64_t samples_rejected = 0;  // decoded, but breaking the rule for a hand's inputs
  int64_t commands_sent = 0, commands_dropped = 0;
  int64_t reconnects = 0, disconnects = 0, watchdog_trips = 0;
  double input_rate_hz = 0.0;       // over the last samples, by the glove's clock if it has one
  double last_sample_age_s = -1.0;  // -1: no sample yet
  double output_rate_hz = 0.0;
  DeviceCapabilities capabilities;  // as announced, under the def's limits
  DeviceCommand last_command;
  bool recording_failed = false;
  // the first command to answer each new sample, microseconds: from when this thread
  // set the sample to the publish of the step that solved it, from that publish to the
  // command's write, and the whole way (the glove's line either side is not in these)
  StepHistogram sample_to_step, step_to_command, sample_to_command;
};

class DeviceLink final : private ProtocolSink {
 public:
  // Drives the hand in `port`'s slot when opened; the port must outlive the link (a
  // world's ports live as long as the world), and its hand may not go while the link
  // holds it (a world refuses to remove a hand a device drives).
  DeviceLink(HandPort& port, const DeviceLinkDef& def, std::unique_ptr<ByteStream> stream,
             std::unique_ptr<GloveProtocol> protocol);
  ~DeviceLink() override;
  DeviceLink(const DeviceLink&) = delete;
  DeviceLink& operator=(const DeviceLink&) = delete;

  // Host: take the hand's port (FRUSTA_ERROR_WRONG_STATE if another glove has it, or the
  // port has no hand), open
  // the glove (a failure is returned: a glove absent at open is an error, not a
  // reconnect) and start the thread.
  frusta_result open();
  // Host: zero the glove's output, stop the thread, close, give the port back to the
  // host. Idempotent.
  void close();

  // Any one thread: the palm pose for gloves without a tracker (ignored when the glove
  // reports its own).
  void set_palm_pose(const vec3& position, const glm::dquat& rotation);

  // One host thread: the newest status, valid until the next call.
  const DeviceLinkStatus& status();

 private:
  struct PalmPose {
    vec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  };

  frusta_result open_glove();
  void run();
  void on_connected(int64_t now);
  void on_disconnected(int64_t now);
  void send_command(int64_t now, const DeviceFeed& feed);
  WatchdogReason check_watchdog(int64_t now, const DeviceFeed& feed) const;
  void apply_capabilities(const DeviceCapabilities& announced);
  void publish_status(int64_t now);
  void write_bytes(bool command);  // commands are counted; handshakes are not

  // ProtocolSink, on the device thread
  void on_sample(const DeviceSample& sample) override;
  void on_capabilities(const DeviceCapabilities& capabilities) override;
  void on_fault(FrameFault fault) override;
  void on_heartbeat() override;

  HandPort& port_;
  DeviceLinkDef def_;
  bool claimed_ = false;  // the host's: this link holds the port
  uint32_t hand_generation_ = 0;  // of the hand in the port, set before the thread starts
  std::unique_ptr<ByteStream> stream_;
  std::unique_ptr<GloveProtocol> protocol_;
  Recorder recorder_;
  bool recording_ = false;

  // the device thread's
  DeviceLinkStatus working_;
  OutputGuard guard_;
  std::vector<uint8_t> out_;
  int64_t now_ns_ = 0;         // of the current turn
  int64_t last_sample_ns_ = 0;  // 0: none since (re)connect
  RateMeter input_rate_;
  int64_t samples_taken_ = 0;  // since (re)connect: the number of a sample without one
  int64_t last_command_ns_ = 0;
  uint64_t sent_step_ = 0;        // the step whose feed the last command carried
  uint64_t answered_input_ = 0;   // the newest input a command has answered (its sequence)
  int64_t next_heartbeat_ns_ = 0;
  int64_t record_start_ns_ = 0;
  int64_t output_period_ns_ = 1000000;
  bool ever_connected_ = false;
  HandState haptic_;

  TripleBuffer<PalmPose> palm_;
  TripleBuffer<DeviceLinkStatus> status_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace frusta
