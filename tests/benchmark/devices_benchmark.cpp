// SPDX-License-Identifier: MIT
// tools/bench devices: end-to-end latency of a glove, over a real serial line (a
// pseudo-terminal), from a sample written on the glove's side to the brake command
// that answers it read back there. A simulated glove alternately curls its index into
// a box and lets go; each change's latency is the time from the write of the first
// sample carrying it to the first command showing it (brake on, brake off). Two
// stimuli: a tap, the index from open (2 mm off the box) to 2 mm into it in one sample
// and back (about 3 m/s at the tip: a fast tap), the latency of the path; and a jump,
// the index from open to 61 % curled in one sample, centimetres at a speed no finger
// reaches, whose steps are the solver sub-stepping that move up to the step budget. The path
// measured is the whole one: the pty to the device thread, its read and decode, the wait
// for the world's next 1 kHz tick, the step (which solves a glove's newest sample), the
// device feed and its wake-up, the output guard, the command's write and the pty back.
// Beside it, the parts: the device thread's own figures (sample set -> step published
// -> command written) and a pty's one-way time, measured alone (a ping-pong). The load
// average before and after says how busy the machine was.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>
#include <vector>

#include "devices/alpha_encoding.h"
#include "devices/device_link.h"
#include "devices/frusta_protocol.h"
#include "devices/glove_calibration.h"
#include "devices/opengloves_protocol.h"
#include "devices/serial_stream.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "core/step_histogram.h"
#include "runtime/world.h"
#include "scenes/binary_glove.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"
#include "scenes/simulated_glove.h"

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;
using scenes::SimulatedGlove;

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

// The glove's side of one protocol: its sample for a curl, what it does with the
// engine's bytes as they come, and whether a command line (or frame) brakes the index.
struct GloveSide {
  const char* name;
  double glove_rate_hz;
  int32_t baud;
  std::function<std::unique_ptr<GloveProtocol>()> protocol;
  std::function<std::string(int curl, int64_t tick)> sample;
  SimulatedGlove::Listener listener;
  // the brake state of every complete command in `bytes` (consumed), after reset()
  std::function<void()> reset;
  std::function<void(std::string* bytes, std::vector<int>* brakes)> commands;
};

GloveSide opengloves_side() {
  GloveSide side;
  side.name = "opengloves";
  side.glove_rate_hz = 1000.0;  // a glove sampling as fast as the engine steps
  side.baud = 115200;
  side.protocol = [] { return std::make_unique<OpenGlovesProtocol>(default_glove_calibration()); };
  side.sample = [](int curl, int64_t) { return "A0B" + std::to_string(curl) + "C0D0E0\n"; };
  side.reset = [] {};
  side.commands = [](std::string* bytes, std::vector<int>* brakes) {
    size_t end;
    while ((end = bytes->find('\n')) != std::string::npos) {
      std::array<int32_t, 5> units{};
      if (decode_alpha_brakes(bytes->substr(0, end), &units)) brakes->push_back(units[1] > 0);
      bytes->erase(0, end + 1);
    }
  };
  return side;
}

// Our binary profile: a 1 kHz glove that takes a command every engine step.
GloveSide binary_side() {
  struct State final : binary_profile::HostSink {
    explicit State(const DeviceCapabilities& caps) : glove(caps), firmware(glove.firmware()) {}
    scenes::BinaryGlove glove;
    SimulatedGlove::Firmware firmware;
    binary_profile::GloveSideDecoder decoder;  // the measuring thread's
    std::vector<int>* brakes = nullptr;
    void on_hello(const binary_profile::Hello&) override {}
    void on_command(const binary_profile::Command& c) override {
      brakes->push_back(c.command.finger_resistance[1] > 0.0);
    }
    void on_heartbeat() override {}
    void on_fault(FrameFault) override {}
  };
  DeviceCapabilities caps;
  caps.input_rate_hz = 1000.0;
  caps.output_rate_hz = 1000.0;
  auto state = std::make_shared<State>(caps);
  const GloveCalibration calibration = default_glove_calibration();
  GloveSide side;
  side.name = "frusta-binary";
  side.glove_rate_hz = 1000.0;
  side.baud = 921600;
  side.protocol = [] { return std::make_unique<FrustaProtocol>(1000, 0); };
  side.sample = [state, calibration](int curl, int64_t tick) {
    for (int j = 0; j < 3; ++j)  // the curl as the OpenGloves calibration reads it
      state->glove.set_angle(FRUSTA_JOINTS_PER_FINGER + 1 + j, calibration.flexion_closed[1][j] * curl / 4095);
    return state->firmware(tick);
  };
  side.listener = state->glove.listener();
  side.reset = [state] { state->decoder.reset(); };
  side.commands = [state](std::string* bytes, std::vector<int>* brakes) {
    state->brakes = brakes;
    state->decoder.feed(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size(), state.get());
    bytes->clear();
  };
  return side;
}

// The engine's side of the line, stamped: when each read brought bytes and each write
// went out, so a transition's time splits into the line in, the engine, the line out.
class StampedStream final : public ByteStream {
 public:
  explicit StampedStream(std::unique_ptr<ByteStream> inner) : inner_(std::move(inner)) {}
  frusta_result open() override { return inner_->open(); }
  void close() override { inner_->close(); }
  bool is_open() const override { return inner_->is_open(); }
  IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) override {
    const IoStatus status = inner_->read(buffer, capacity, timeout_us, received);
    if (*received > 0) stamp(reads_);
    return status;
  }
  IoStatus write(const uint8_t* data, size_t size, bool* dropped) override {
    const IoStatus status = inner_->write(data, size, dropped);
    stamp(writes_);
    return status;
  }
  const std::string& name() const override { return inner_->name(); }
  bool wakes_on(const Wakeup* wakeup) override { return inner_->wakes_on(wakeup); }
  // the first read at or after t, and the last write at or before t (0: none)
  int64_t read_after(int64_t t) const { return find(reads_, t, true); }
  int64_t write_before(int64_t t) const { return find(writes_, t, false); }

 private:
  void stamp(std::vector<int64_t>& into) {
    std::lock_guard<std::mutex> lock(mutex_);
    into.push_back(now_ns());
  }
  int64_t find(const std::vector<int64_t>& in, int64_t t, bool after) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (after) {
      const auto it = std::lower_bound(in.begin(), in.end(), t);
      return it == in.end() ? 0 : *it;
    }
    const auto it = std::upper_bound(in.begin(), in.end(), t);
    return it == in.begin() ? 0 : *(it - 1);
  }
  std::unique_ptr<ByteStream> inner_;
  mutable std::mutex mutex_;
  std::vector<int64_t> reads_, writes_;
};

// The glove's curls (OpenGloves units, 0..4095, the index's three flexions as the
// default calibration reads them) that a stimulus alternates between.
struct Stimulus {
  const char* name;
  int released, pressed;
};

HandState index_curled(int curl) {
  const GloveCalibration calibration = default_glove_calibration();
  HandState state = scenes::open_hand();
  for (int j = 0; j < 3; ++j)
    state.angles[FRUSTA_JOINTS_PER_FINGER + 1 + j] = calibration.flexion_closed[1][j] * curl / 4095;
  return state;
}

// The index's signed distance (metres) to the box as the engine sees it, its leaf
// spheres at `centre`, at a curl: every segment solid, exactly (the pad nears it first).
double index_gap(const HandModel& model, const SphereTree& box, const vec3& centre, int curl) {
  HandPose pose;
  forward_kinematics(model, index_curled(curl), pose);
  double gap = INFINITY;
  for (int segment = 0; segment < FRUSTA_SEGMENTS_PER_FINGER; ++segment) {
    const SegmentFrame frame = make_segment_frame(finger_segment(model, pose, FRUSTA_FINGER_INDEX, segment));
    for (const Sphere& leaf : box.leaves)
      gap = std::min(gap, exact_proximity(frame, {centre + leaf.center, leaf.radius}).distance);
  }
  return gap;
}

// The least curl whose index is within `gap` of the box: over the first 500 units
// it only goes deeper (1 cm in at 500; further curled it sweeps through the box).
int curl_at_gap(const HandModel& model, const SphereTree& box, const vec3& centre, double gap) {
  int lo = 0, hi = 500;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (index_gap(model, box, centre, mid) <= gap) hi = mid; else lo = mid + 1;
  }
  return lo;
}

struct Latency {
  StepHistogram line_in, engine, line_out;  // a transition's parts
  StepHistogram press, release, all;
  double world_step_p50 = 0.0, world_step_p99 = 0.0, world_step_max = 0.0;  // its own, us
  int64_t missed = 0;
  double output_rate_hz = 0.0;
  DeviceLinkStatus link;  // its own figures of the same run
};

// The box the index presses, 2 mm beyond its open tip.
vec3 press_box_centre(const HandModel& model) {
  return scenes::index_press_box_centre(model, 0.5 * scenes::test_box_spec("press_box").size.x, 0.002);
}

Latency measure(const GloveSide& side, const Stimulus& stimulus, int transitions) {
  const HandModel model = make_hand_model(default_hand_def());
  World world(WorldDef{});
  HandHandle hand;
  world.add_hand(model, &hand);
  ObjectDef box;
  box.pose.position = press_box_centre(model);
  ObjectHandle handle;
  world.add_object(scenes::test_box("press_box"), box, &handle);
  world.start();

  std::atomic<int> curl{stimulus.released};
  std::atomic<int64_t> changed_ns{0};  // when the first sample with the new curl went out
  std::atomic<int> sent_curl{stimulus.released};
  const std::string path = "/tmp/frusta-bench-" + std::to_string(getpid()) + "-glove";
  SimulatedGlove glove(path, side.glove_rate_hz, [&](int64_t tick) {
    const int c = curl.load();
    if (c != sent_curl.exchange(c)) changed_ns = now_ns();
    return side.sample(c, tick);
  }, side.listener);
  DeviceLinkDef def;
  def.host_timeout_s = 0.0;  // this host does not read snapshots
  def.rates.max_force_rate = 1e9;  // the first command after contact brakes at once
  auto stamped = std::make_unique<StampedStream>(std::make_unique<SerialStream>(path, side.baud));
  const StampedStream& line = *stamped;
  DeviceLink link(world.port(hand.slot), def, std::move(stamped), side.protocol());
  link.open();

  Latency result;
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (int t = 0; t < 2 * transitions; ++t) {
    const bool pressing = t % 2 == 0;
    glove.clear_received();
    changed_ns = 0;
    curl = pressing ? stimulus.pressed : stimulus.released;
    // the first command after the change that shows it
    std::string bytes;
    std::vector<int> brakes;
    bool seen = false;
    const auto deadline = Clock::now() + std::chrono::milliseconds(500);
    while (!seen && Clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      const int64_t since = changed_ns.load();
      if (since == 0) continue;
      side.reset();
      for (const SimulatedGlove::Chunk& chunk : glove.chunks()) {
        if (seen) break;
        bytes += chunk.bytes;
        brakes.clear();
        side.commands(&bytes, &brakes);
        for (int brake : brakes) {
          if (chunk.time_ns >= since && (brake == 1) == pressing) {
            const double us = static_cast<double>(chunk.time_ns - since) / 1e3;
            (pressing ? result.press : result.release).record(us);
            result.all.record(us);
            const int64_t read = line.read_after(since), wrote = line.write_before(chunk.time_ns);
            if (read > 0 && wrote >= read) {
              result.line_in.record(static_cast<double>(read - since) / 1e3);
              result.engine.record(static_cast<double>(wrote - read) / 1e3);
              result.line_out.record(static_cast<double>(chunk.time_ns - wrote) / 1e3);
            }
            seen = true;
            break;
          }
        }
      }
      bytes.clear();
    }
    if (!seen) ++result.missed;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // rest in the new state (a tap settles in a step or two)
  }
  result.link = link.status();
  const WorldSnapshot& snapshot = world.read();
  result.world_step_p50 = snapshot.step_us_p50;
  result.world_step_p99 = snapshot.step_us_p99;
  result.world_step_max = snapshot.step_us_max;
  result.output_rate_hz = result.link.output_rate_hz;
  link.close();
  world.stop();
  return result;
}

// One way over a pseudo-terminal, alone: bytes written on one side to their read on the
// other by a thread blocked in ppoll, as the glove and the device thread are. Both
// directions; microseconds.
StepHistogram pty_one_way(int round_trips) {
  StepHistogram one_way;
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) return one_way;
  termios tty{};
  tcgetattr(master, &tty);
  cfmakeraw(&tty);
  tcsetattr(master, TCSANOW, &tty);
  const int slave = open(ptsname(master), O_RDWR | O_NOCTTY);
  tcgetattr(slave, &tty);
  cfmakeraw(&tty);
  tcsetattr(slave, TCSANOW, &tty);
  std::atomic<bool> stop{false};
  std::atomic<int64_t> sent_ns{0};
  // the far side answers each byte; the time it read it is one way out
  std::thread echo([&] {
    char b[64];
    while (!stop) {
      pollfd p{slave, POLLIN, 0};
      const timespec wait{0, 50'000'000};
      if (ppoll(&p, 1, &wait, nullptr) <= 0) continue;
      const ssize_t n = read(slave, b, sizeof b);
      if (n <= 0) continue;
      one_way.record(static_cast<double>(now_ns() - sent_ns.load()) / 1e3);
      sent_ns = now_ns();
      if (write(slave, b, static_cast<size_t>(n)) != n) break;
    }
  });
  char b[64] = {'x'};
  for (int i = 0; i < round_trips; ++i) {
    sent_ns = now_ns();
    if (write(master, b, 1) != 1) break;
    pollfd p{master, POLLIN, 0};
    const timespec wait{0, 100'000'000};
    if (ppoll(&p, 1, &wait, nullptr) <= 0) continue;
    if (read(master, b, sizeof b) <= 0) break;
    one_way.record(static_cast<double>(now_ns() - sent_ns.load()) / 1e3);
    std::this_thread::sleep_for(std::chrono::microseconds(500));  // a glove's pace
  }
  stop = true;
  echo.join();
  close(slave);
  close(master);
  return one_way;
}

std::string load_average() {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) < 3) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", load[0], load[1], load[2]);
  return text;
}

void print_histogram(const char* name, const StepHistogram& h, const char* end) {
  std::printf("\"%s_p50\": %.0f, \"%s_p99\": %.0f, \"%s_max\": %.0f%s", name, h.percentile(0.5),
              name, h.percentile(0.99), name, h.max(), end);
}

}  // namespace
}  // namespace frusta

int main() {
  using namespace frusta;
  constexpr int kTransitions = 500;  // each way: 1000 latencies, so p99 is not the second largest
  const HandModel model = make_hand_model(default_hand_def());
  const vec3 centre = press_box_centre(model);
  const SphereTree& box = scenes::test_box("press_box")->tree;
  const Stimulus stimuli[] = {
      {"tap", 0, curl_at_gap(model, box, centre, -0.002)},
      {"jump", 0, 2500}};
  std::printf("{\n\"suite\": \"devices\",\n\"transitions\": %d,\n\"load_before\": \"%s\",\n"
              "\"latency_us\": [\n",
              kTransitions, load_average().c_str());
  const GloveSide sides[] = {opengloves_side(), binary_side()};
  bool first = true;
  for (const Stimulus& stimulus : stimuli) {
    for (const GloveSide& side : sides) {
      const Latency l = measure(side, stimulus, kTransitions);
      std::printf("%s  {\"protocol\": \"%s\", \"stimulus\": \"%s\", \"curls\": [%d, %d], "
                  "\"glove_rate_hz\": %.0f, \"output_rate_hz\": %.0f, ",
                  first ? "" : ",\n", side.name, stimulus.name, stimulus.released, stimulus.pressed,
                  side.glove_rate_hz, l.output_rate_hz);
      first = false;
      print_histogram("glove_to_command", l.all, ", ");
      print_histogram("press", l.press, ", ");
      print_histogram("release", l.release, ",\n   ");
      print_histogram("line_in", l.line_in, ", ");
      print_histogram("engine", l.engine, ", ");
      print_histogram("line_out", l.line_out, ",\n   ");
      print_histogram("link_sample_to_step", l.link.sample_to_step, ", ");
      print_histogram("link_step_to_command", l.link.step_to_command, ", ");
      print_histogram("link_sample_to_command", l.link.sample_to_command, ", ");
      std::printf("\"world_step_p50\": %.0f, \"world_step_p99\": %.0f, \"world_step_max\": %.0f, ",
                  l.world_step_p50, l.world_step_p99, l.world_step_max);
      std::printf("\"missed\": %lld}", static_cast<long long>(l.missed));
    }
  }
  std::printf("\n],\n\"pty_one_way_us\": {");
  print_histogram("one_way", pty_one_way(2000), "");
  std::printf("},\n\"load_after\": \"%s\"\n}\n", load_average().c_str());
  return 0;
}
