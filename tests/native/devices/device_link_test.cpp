// SPDX-License-Identifier: MIT
// A glove on a real serial line (a pseudo-terminal) driving a hand of a world on its
// 1 kHz thread: samples in, brake commands read back on the glove's side, and every
// way a glove fails: unplugged mid-stream, back again, garbage on the line, NaN and
// absurd angles, too slow or too fast, frozen; and an engine or host that stops.
// No check here holds a wall clock against a rate or a count: rates come from the
// glove's own stamps, and each check waits for the state it checks, with a deadline
// that only turns a hang into a failure. A loaded machine makes them slower, not red.
#include "devices/device_link.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "devices/alpha_encoding.h"
#include "devices/frusta_protocol.h"
#include "devices/opengloves_protocol.h"
#include "devices/serial_stream.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "core/periodic_clock.h"
#include "runtime/world.h"
#include "scenes/binary_glove.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"
#include "scenes/process_probe.h"
#include "scenes/simulated_glove.h"
#include "collecting_sink.h"

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;
using scenes::SimulatedGlove;
using scenes::temp_path;
using scenes::thread_count;
using scenes::thread_count_becomes;
constexpr int kIndex = 1;
constexpr int kIndexFlexion1 = kIndex * FRUSTA_JOINTS_PER_FINGER + 1;
// seconds: a wait's deadline, which only a hang reaches (a machine running fuzzers and
// builds on both cores beside these tests slowed single waits past 30 s)
constexpr double kPatience = 120.0;

// A right hand over a 3 cm box whose face lies 2 mm from the open index fingertip, on
// the side a curling index moves to: a curl presses the finger in, and the world asks
// the glove to brake that finger (and only that one).
struct Scene {
  Scene() : world(WorldDef{}) {
    const HandModel model = make_hand_model(default_hand_def());
    const double half = 0.5 * scenes::test_box_spec("press_box").size.x;
    ObjectDef box;
    box.pose.position = scenes::index_press_box_centre(model, half, 0.002);
    EXPECT_EQ(world.add_hand(model, &hand), FRUSTA_OK);
    ObjectHandle handle;
    EXPECT_EQ(world.add_object(scenes::test_box("press_box"), box, &handle), FRUSTA_OK);
    EXPECT_EQ(world.start(), FRUSTA_OK);
  }
  ~Scene() { world.stop(); }
  World world;
  HandHandle hand;
};

// LucidGloves firmware: five curls a line; the index's is what the test sets.
struct OpenGlovesFirmware {
  std::atomic<int> index_curl{0};
  SimulatedGlove::Firmware firmware() {
    return [this](int64_t) {
      return "A0B" + std::to_string(index_curl.load()) + "C0D0E0\n";
    };
  }
};

std::unique_ptr<DeviceLink> open_link(World& world, const std::string& path,
                                      DeviceLinkDef def = DeviceLinkDef{}) {
  def.protocol_name = "opengloves";
  auto link = std::make_unique<DeviceLink>(
      world.port(0), def, std::make_unique<SerialStream>(path, 115200),
      std::make_unique<OpenGlovesProtocol>(default_glove_calibration()));
  EXPECT_EQ(link->open(), FRUSTA_OK);
  return link;
}

// Until done(), at most `seconds`. With a world, the host's loop: it reads snapshots
// meanwhile (so the host watchdog sees a live host); without, a host that stopped.
bool wait(World* reading, const std::function<bool()>& done, double seconds = kPatience) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    if (reading != nullptr) reading->read();
    if (done()) return true;
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

bool wait_until(World& world, const std::function<bool()>& done, double seconds = kPatience) {
  return wait(&world, done, seconds);
}

// The first status (one snapshot: its fields agree with each other) that is `wanted`;
// if none comes, the failure shows the last one.
testing::AssertionResult wait_status(DeviceLink& link, World* reading,
                                     const std::function<bool(const DeviceLinkStatus&)>& wanted,
                                     DeviceLinkStatus* out) {
  if (wait(reading, [&] {
        *out = link.status();
        return wanted(*out);
      }))
    return testing::AssertionSuccess();
  const DeviceLinkStatus& s = *out;
  return testing::AssertionFailure()
         << "the last status: state " << static_cast<int>(s.state) << ", watchdog "
         << static_cast<int>(s.watchdog) << ", frames_ok " << s.frames_ok << ", corrupt "
         << s.frames_corrupt << ", truncated " << s.frames_truncated << ", out of range "
         << s.frames_out_of_range << ", rejected " << s.samples_rejected << ", commands "
         << s.commands_sent << " (" << s.commands_dropped << " dropped), trips " << s.watchdog_trips
         << ", input " << s.input_rate_hz << " Hz, last sample " << s.last_sample_age_s << " s ago";
}

// The last complete brake line the glove received.
std::array<int32_t, 5> last_brakes(const SimulatedGlove& glove) {
  const std::string all = glove.received();
  std::array<int32_t, 5> units{-1, -1, -1, -1, -1};
  const size_t end = all.rfind('\n');
  if (end == std::string::npos) return units;
  const size_t start = all.rfind('\n', end - 1);
  decode_alpha_brakes(all.substr(start == std::string::npos ? 0 : start + 1, end - start), &units);
  return units;
}

// The world's first hand as the host sees it; an unsolved one before a step applied
// its addition.
const HandSnapshot& first_hand(World& world) {
  static const HandSnapshot none;
  const HandSlot& slot = world.read().hands[0];
  return slot.present ? *slot.hand : none;
}

// The index's first flexion as the host sees the glove's input.
double index_flexion(World& world) { return first_hand(world).haptic.angles[kIndexFlexion1]; }

// The index's first flexion for an OpenGloves curl reading.
double curl_flexion(int64_t curl) {
  return default_glove_calibration().flexion_closed[kIndex][0] * static_cast<double>(curl) / 4095;
}

bool all_zero(const DeviceCommand& c) {
  for (double r : c.finger_resistance)
    if (r != 0.0) return false;
  return true;
}

// A command that brakes is only sent with the watchdog clear, and the status published
// with it says so.
bool braking(const DeviceLinkStatus& s) {
  return s.watchdog == WatchdogReason::kNone && s.last_command.finger_resistance[kIndex] > 0.0;
}

// The hand as the host sees it, for a failure's message.
std::string describe_hand(World& world) {
  const HandSnapshot& h = first_hand(world);
  std::ostringstream out;
  out << "the hand: solved " << h.solved << ", index flexion haptic " << h.haptic.angles[kIndexFlexion1]
      << ", graphic " << h.graphic.angles[kIndexFlexion1] << ", contacts " << h.contact_count
      << ", lagging " << h.stats.lagging << ", step " << world.read().step;
  return out.str();
}

// The glove speaks with the hand open and the world solves it so: a hand whose first
// input is already inside the box would be moved out of it (depenetrated), not pressed
// into it, so this comes before any curl.
testing::AssertionResult solved_open(World& world) {
  if (wait_until(world, [&] {
        const HandSnapshot& hand = first_hand(world);
        return hand.solved && hand.haptic.angles[kIndexFlexion1] == 0.0;
      }))
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << describe_hand(world);
}

// Then the glove curls the index into the box. Done once the host's view of the world
// shows the curl (a step or more after the world acted on it) followed by a graphic
// hand that touches the box. A world behind its deadline (under ThreadSanitizer, on a
// loaded machine) follows the curl over several steps, and the finger leaves the face
// on the way while its distal joints curl round, its brake off for those steps: the
// press is steady only once the hand has caught up.
testing::AssertionResult curled_in(World& world, double flexion, double tolerance) {
  if (wait_until(world, [&] {
        const HandSnapshot& hand = first_hand(world);
        return std::fabs(hand.haptic.angles[kIndexFlexion1] - flexion) <= tolerance && !hand.stats.lagging &&
               hand.contact_count > 0;
      }))
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << describe_hand(world) << " for " << flexion;
}

// An OpenGloves glove's press: open, then curled in, and then the glove brakes.
testing::AssertionResult press(World& world, OpenGlovesFirmware& firmware, DeviceLink& link,
                               const SimulatedGlove& glove) {
  if (!wait_until(world, [&] { return link.status().frames_ok > 3; }))
    return testing::AssertionFailure() << "no samples";
  if (testing::AssertionResult open = solved_open(world); !open) return open;
  firmware.index_curl = 1500;
  if (testing::AssertionResult in = curled_in(world, curl_flexion(1500), 1e-9); !in) return in;
  if (!wait_until(world, [&] { return last_brakes(glove)[kIndex] > 0; }))
    return testing::AssertionFailure() << "no brake; " << describe_hand(world);
  return testing::AssertionSuccess();
}

// The same with our binary profile, in radians on the wire (to its 1e-4 rad).
testing::AssertionResult press(World& world, scenes::BinaryGlove& firmware) {
  if (testing::AssertionResult open = solved_open(world); !open) return open;
  const GloveCalibration calibration = default_glove_calibration();
  for (int j = 0; j < 3; ++j)
    firmware.set_angle(kIndexFlexion1 + j, calibration.flexion_closed[kIndex][j] * 1500 / 4095);
  return curled_in(world, curl_flexion(1500), 0.5 * binary_profile::kAngleUnit);
}

TEST(rateMeter, ByTheGlovesClockAndCountTheRateIsTheGlovesWhateverArrives) {
  RateMeter meter;
  meter.add(0, 0, true);
  EXPECT_EQ(meter.rate_hz(), 0.0) << "one stamp is no rate";
  for (int64_t i = 1; i < 200; ++i) {
    if (i % 7 == 3) continue;  // lost on the way: the glove's count says so
    meter.add(i * 2000000, i, true);  // 500 a second by the glove's clock
    ASSERT_DOUBLE_EQ(meter.rate_hz(), 500.0) << i;
  }
  // the glove restarted (a reconnect, a reset): its clock starts over, and so does the window
  for (int64_t i = 0; i < 3; ++i) meter.add(i * 10000000, i, true);
  EXPECT_DOUBLE_EQ(meter.rate_hz(), 100.0);
  // a glove without a clock is timed by arrival, in a window of its own
  meter.add(7000000000, 1, false);
  meter.add(7020000000, 2, false);
  EXPECT_DOUBLE_EQ(meter.rate_hz(), 50.0);
}

TEST(rateMeter, ByArrivalABurstIsNoInfiniteRateAndLeavesWithTheWindow) {
  // 100 a second, but 4 samples held up 40 ms and read at once with the 5th
  RateMeter meter;
  int64_t i = 0;
  for (; i < 100; ++i) meter.add(i * 10000000, i, false);
  EXPECT_DOUBLE_EQ(meter.rate_hz(), 100.0);
  for (; i < 105; ++i) {
    meter.add(104 * 10000000, i, false);
    EXPECT_TRUE(std::isfinite(meter.rate_hz()) && meter.rate_hz() > 0.0) << i;
  }
  for (; i < 105 + RateMeter::kWindow; ++i) meter.add(i * 10000000, i, false);
  EXPECT_DOUBLE_EQ(meter.rate_hz(), 100.0) << "the burst has left the window";
}

TEST(deviceLink, OpenGlovesGloveDrivesTheHandAndReadsBrakesBack) {
  Scene scene;
  OpenGlovesFirmware firmware;
  SimulatedGlove glove(temp_path("glove"), 100.0, firmware.firmware());
  auto link = open_link(scene.world, glove.path());

  // samples taken, and brake lines back: the hand is open, every brake released. An
  // OpenGloves line carries no clock: its rate is its arrival's, which a loaded machine
  // bends (RateMeter's tests check the measuring), and lines read in one go share an
  // arrival, so here only that a rate comes once they have not all come at once
  DeviceLinkStatus open;
  ASSERT_TRUE(wait_status(*link, &scene.world, [&](const DeviceLinkStatus& s) {
    return s.frames_ok >= 20 && s.input_rate_hz > 0.0 && last_brakes(glove)[0] >= 0;
  }, &open)) << "; the glove sent " << glove.frames_sent() << " frames and read "
             << glove.received().size() << " bytes";
  EXPECT_EQ(open.state, LinkState::kConnected);
  EXPECT_DOUBLE_EQ(open.output_rate_hz, 100.0);  // OpenGloves' line rate, under the world's
  EXPECT_EQ(last_brakes(glove), (std::array<int32_t, 5>{0, 0, 0, 0, 0}));
  EXPECT_NEAR(index_flexion(scene.world), 0.0, 1e-12);

  ASSERT_TRUE(press(scene.world, firmware, *link, glove))
      << index_flexion(scene.world) << "; the glove read " << glove.received().substr(0, 200);
  const std::array<int32_t, 5> brakes = last_brakes(glove);
  EXPECT_EQ(brakes[0] + brakes[2] + brakes[3] + brakes[4], 0) << "only the index touches";
  // (the status follows the command the glove read a moment later)
  DeviceLinkStatus pressing;
  ASSERT_TRUE(wait_status(*link, &scene.world, [](const DeviceLinkStatus& s) {
    return braking(s) && s.commands_sent > 20;
  }, &pressing));
  EXPECT_EQ(pressing.frames_corrupt + pressing.frames_truncated + pressing.samples_rejected, 0);
}

// Our binary profile on the same line: the handshake announces a 500 Hz glove with
// brakes and fingertip forces and lower limits than ours; samples come at its rate, by
// its clock; the commands it reads back carry both outputs, under its limits, in order.
TEST(deviceLink, BinaryProfileGloveHandshakesDrivesTheHandAndReadsCommandsBack) {
  Scene scene;
  DeviceCapabilities caps;
  caps.outputs = kOutputFingerResistance | kOutputFingertipForce;
  caps.max_finger_resistance = 6.0;
  caps.max_fingertip_force = 4.0;
  caps.input_rate_hz = 500.0;
  caps.output_rate_hz = 500.0;
  scenes::BinaryGlove firmware(caps);
  SimulatedGlove glove(temp_path("glove"), 500.0, firmware.firmware(), firmware.listener());
  DeviceLinkDef def;
  def.protocol_name = "frusta";
  auto link = std::make_unique<DeviceLink>(scene.world.port(0), def,
                                           std::make_unique<SerialStream>(glove.path(), 921600),
                                           std::make_unique<FrustaProtocol>(500, 0));
  ASSERT_EQ(link->open(), FRUSTA_OK);

  DeviceLinkStatus open;
  ASSERT_TRUE(wait_status(*link, &scene.world, [](const DeviceLinkStatus& s) {
    return s.capabilities.protocol_version != 0 && s.frames_ok >= 2;
  }, &open));
  EXPECT_EQ(open.capabilities.protocol_version, binary_profile::kVersion);
  EXPECT_EQ(open.capabilities.outputs, caps.outputs);
  EXPECT_DOUBLE_EQ(open.capabilities.max_finger_resistance, 6.0) << "the glove's, under ours";
  EXPECT_DOUBLE_EQ(open.output_rate_hz, 500.0) << "the glove's, under the world's 1 kHz";
  EXPECT_DOUBLE_EQ(open.input_rate_hz, 500.0) << "by the glove's stamps, however late they were read";
  EXPECT_EQ(open.frames_corrupt + open.frames_truncated + open.frames_out_of_range, 0);
  // the handshake: HELLO (again each heartbeat until CAPS comes), then HEARTBEATs only
  ASSERT_TRUE(wait_until(scene.world, [&] { return firmware.heartbeats() > 0; }));
  EXPECT_GE(firmware.hellos(), 1);
  EXPECT_EQ(firmware.hellos_after_heartbeat(), 0);

  // curl the index into the box as the OpenGloves test does
  ASSERT_TRUE(press(scene.world, firmware));
  // both outputs on (the tip force rises from zero at the rate limit)
  ASSERT_TRUE(wait_until(scene.world, [&] {
    const auto commands = firmware.commands();
    if (commands.empty()) return false;
    const DeviceCommand& c = commands.back().command.command;
    return c.finger_resistance[kIndex] > 0.0 && glm::length(c.fingertip_force[kIndex]) > 0.0;
  }));
  DeviceLinkStatus pressing;
  ASSERT_TRUE(wait_status(*link, &scene.world, braking, &pressing)) << describe_hand(scene.world);

  // every command it read: the blocks it renders (once it has said which), under its
  // limits (plus each component's rounding to the wire's 0.01 N), only the index's, and
  // in sequence but for those the link dropped: a glove thread that a loaded machine
  // leaves unscheduled stops draining its line, and the link drops a command rather
  // than wait (counted; what part of one went out is a bad frame to the glove, which
  // frusta_protocol_test shows the reader skips)
  const auto commands = firmware.commands();
  const double force_limit = 4.0 + std::sqrt(3.0) * 0.5 * binary_profile::kForceUnit;
  bool announced = false;
  size_t bad = 0;
  int64_t skipped = 0;
  for (size_t i = 0; i < commands.size(); ++i) {
    const binary_profile::Command& c = commands[i].command;
    announced |= c.outputs == caps.outputs;
    const uint16_t step = i == 0 ? 1 : static_cast<uint16_t>(c.sequence - commands[i - 1].command.sequence);
    skipped += step - 1;
    bool ok = c.outputs == (announced ? caps.outputs : kOutputFingerResistance) &&
              c.command.finger_resistance[kIndex] <= 6.0 &&
              glm::length(c.command.fingertip_force[kIndex]) <= force_limit && step >= 1;
    for (int f : {0, 2, 3, 4})
      ok &= c.command.finger_resistance[f] == 0.0 && glm::length(c.command.fingertip_force[f]) == 0.0;
    if (!ok && bad++ == 0) ADD_FAILURE() << "command " << i << " of " << commands.size();
  }
  EXPECT_EQ(bad, 0u);
  EXPECT_TRUE(announced);
  const DeviceLinkStatus after = link->status();  // counts at least those the glove missed
  EXPECT_LE(skipped, after.commands_dropped);
  EXPECT_EQ(firmware.hellos_after_heartbeat(), 0);
  EXPECT_EQ(pressing.frames_corrupt + pressing.frames_truncated + pressing.frames_out_of_range, 0);
}

TEST(deviceLink, UnplugZeroesAndReplugResumesFromZeroAtTheRiseRate) {
  Scene scene;
  OpenGlovesFirmware firmware;
  SimulatedGlove glove(temp_path("glove"), 100.0, firmware.firmware());
  DeviceLinkDef def;
  def.rates.max_force_rate = 50.0;    // newtons per second: a rise over several commands
  def.reconnect_interval_s = 0.005;  // back soon after the glove is
  auto link = open_link(scene.world, glove.path(), def);
  ASSERT_TRUE(press(scene.world, firmware, *link, glove));
  const double held = index_flexion(scene.world);

  glove.unplug();
  // the line tells the link (its read fails), not the watchdog: it says disconnected
  DeviceLinkStatus gone;
  ASSERT_TRUE(wait_status(*link, &scene.world, [](const DeviceLinkStatus& s) {
    return s.state == LinkState::kDisconnected;
  }, &gone));
  EXPECT_TRUE(all_zero(gone.last_command));
  EXPECT_EQ(gone.watchdog, WatchdogReason::kDisconnected);
  EXPECT_EQ(gone.disconnects, 1);
  // the world runs on with the hand where the glove left it
  const uint64_t step = scene.world.read().step;
  EXPECT_TRUE(wait_until(scene.world, [&] { return scene.world.read().step > step + 50; }));
  EXPECT_DOUBLE_EQ(index_flexion(scene.world), held);

  glove.clear_received();
  const int64_t plugged_ns = steady_ns();
  glove.plug_in();
  DeviceLinkStatus back;
  ASSERT_TRUE(wait_status(*link, &scene.world, [](const DeviceLinkStatus& s) { return s.reconnects == 1; }, &back));
  EXPECT_EQ(back.state, LinkState::kConnected);
  ASSERT_TRUE(wait_until(scene.world, [&] { return last_brakes(glove)[kIndex] > 0; }));
  // back from a disconnect the brake starts from zero and rises at the rate limit, not
  // at the force it had: the link connected after the plug-in and the glove read each
  // line after it was sent, so no line may exceed the rate times the time since the
  // plug-in (in brake units, rounded), however the threads were scheduled
  const GloveCalibration calibration = default_glove_calibration();
  const double units_per_newton = calibration.brake_units / calibration.brake_full_scale;
  std::string pending;
  int lines = 0, broken = 0;  // broken: a command the link dropped part of (counted)
  for (const SimulatedGlove::Chunk& chunk : glove.chunks()) {
    pending += chunk.bytes;
    for (size_t end = pending.find('\n'); end != std::string::npos; end = pending.find('\n')) {
      const std::string line = pending.substr(0, end);
      pending.erase(0, end + 1);
      std::array<int32_t, 5> units{};
      if (!decode_alpha_brakes(line, &units)) {
        ++broken;
        continue;
      }
      const double since_s = static_cast<double>(chunk.time_ns - plugged_ns) / 1e9;
      EXPECT_LE(units[kIndex], def.rates.max_force_rate * since_s * units_per_newton + 0.5)
          << line << ", read " << since_s * 1e3 << " ms after the plug-in";
      ++lines;
    }
  }
  EXPECT_GT(lines, 0);
  EXPECT_LE(broken, link->status().commands_dropped);
}

TEST(deviceLink, CorruptAndTruncatedFramesAreCountedAndDropped) {
  Scene scene;
  OpenGlovesFirmware firmware;
  firmware.index_curl = 1000;
  SimulatedGlove glove(temp_path("glove"), 100.0, firmware.firmware());
  auto link = open_link(scene.world, glove.path());
  const std::string garbage[] = {"A1x\n", "95C4095\n", std::string("\xff\xfe\x00\n", 4), "A99999\n",
                                 std::string(400, 'B') + "\n"};
  // what the decoder makes of these lines alone: the glove writes its frames and these
  // whole, so on the wire each stays a line of its own
  OpenGlovesProtocol alone(default_glove_calibration());
  std::vector<uint8_t> handshake;
  alone.start(&handshake);
  Collect each;
  for (const std::string& g : garbage)
    alone.feed(reinterpret_cast<const uint8_t*>(g.data()), g.size(), &each);
  ASSERT_GT(each.corrupt, 0);
  ASSERT_GT(each.truncated, 0);
  ASSERT_GT(each.out_of_range, 0);
  ASSERT_TRUE(each.samples.empty());

  for (int round = 0; round < 10; ++round)
    for (const std::string& g : garbage) glove.write_raw(g);
  DeviceLinkStatus s;
  ASSERT_TRUE(wait_status(*link, &scene.world, [&](const DeviceLinkStatus& t) {
    return t.frames_corrupt >= 10 * each.corrupt && t.frames_truncated >= 10 * each.truncated &&
           t.frames_out_of_range >= 10 * each.out_of_range && t.frames_ok >= 30;
  }, &s));
  EXPECT_EQ(s.frames_corrupt, 10 * each.corrupt);
  EXPECT_EQ(s.frames_truncated, 10 * each.truncated);
  EXPECT_EQ(s.frames_out_of_range, 10 * each.out_of_range);
  EXPECT_EQ(s.state, LinkState::kConnected);
  EXPECT_TRUE(wait_until(scene.world, [&] { return std::fabs(index_flexion(scene.world) - curl_flexion(1000)) < 1e-9; }))
      << index_flexion(scene.world);
}

// Our own test of the link's last check: a protocol that passes angles through as
// text, so a glove can send what no real encoding can (NaN, 1e9 radians).
class AnglesAsText final : public GloveProtocol {
 public:
  DeviceCapabilities default_capabilities() const override { return DeviceCapabilities{}; }
  void start(std::vector<uint8_t>*) override { line_.clear(); }
  void feed(const uint8_t* data, size_t size, ProtocolSink* sink) override {
    for (size_t i = 0; i < size; ++i) {
      if (data[i] != '\n') {
        line_ += static_cast<char>(data[i]);
        continue;
      }
      DeviceSample s;
      std::istringstream in(line_);
      std::string word;
      for (double& a : s.angles) {
        in >> word;
        a = std::strtod(word.c_str(), nullptr);
      }
      line_.clear();
      sink->on_sample(s);
    }
  }
  void encode(const DeviceCommand&, const DeviceCapabilities&, std::vector<uint8_t>*) override {}
  void encode_heartbeat(std::vector<uint8_t>*) override {}

 private:
  std::string line_;
};

TEST(deviceLink, NaNAndAbsurdAnglesAreRejected) {
  Scene scene;
  std::atomic<int> kind{0};
  SimulatedGlove glove(temp_path("glove"), 100.0, [&](int64_t) {
    std::string line;
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) {
      const bool bad = j == kIndexFlexion1 && kind != 0;
      line += bad ? (kind == 1 ? "nan " : "1e9 ") : "0.1 ";
    }
    return line + "\n";
  });
  DeviceLinkDef def;
  auto link = std::make_unique<DeviceLink>(scene.world.port(0), def,
                                           std::make_unique<SerialStream>(glove.path(), 115200),
                                           std::make_unique<AnglesAsText>());
  ASSERT_EQ(link->open(), FRUSTA_OK);
  // the hand's first pose presses into the box: the world's first step with it moves
  // the graphic hand out (milliseconds; far more under the sanitizers), so wait for it
  ASSERT_TRUE(wait_until(scene.world, [&] { return std::fabs(index_flexion(scene.world) - 0.1) < 1e-12; }))
      << index_flexion(scene.world);
  for (int k : {1, 2}) {
    kind = k;
    const int64_t rejected = link->status().samples_rejected;
    ASSERT_TRUE(wait_until(scene.world, [&] { return link->status().samples_rejected > rejected + 5; }));
    EXPECT_NEAR(index_flexion(scene.world), 0.1, 1e-12) << "the hand kept its last good pose";
  }
  // no good sample for a watchdog period: the glove is taken for stalled and released
  DeviceLinkStatus stalled;
  EXPECT_TRUE(wait_status(*link, &scene.world, [](const DeviceLinkStatus& s) {
    return s.watchdog == WatchdogReason::kInputStalled && all_zero(s.last_command);
  }, &stalled));
  EXPECT_NEAR(index_flexion(scene.world), 0.1, 1e-12);
}

// A glove that samples at half or twice the rate it announced: the link measures the
// rate it really sends at, by its own clock, and takes it as live either way.
TEST(deviceLink, AGloveAtHalfOrTwiceItsAnnouncedRateIsMeasuredByItsClockAndDrivesTheHand) {
  for (double rate : {50.0, 200.0}) {
    Scene scene;
    DeviceCapabilities caps;  // brakes at 100 a second, both ways
    caps.input_rate_hz = 100.0;
    caps.output_rate_hz = 100.0;
    scenes::BinaryGlove firmware(caps, rate);
    SimulatedGlove glove(temp_path("glove"), rate, firmware.firmware(), firmware.listener());
    DeviceLink link(scene.world.port(0), DeviceLinkDef{}, std::make_unique<SerialStream>(glove.path(), 921600),
                    std::make_unique<FrustaProtocol>());
    ASSERT_EQ(link.open(), FRUSTA_OK);
    DeviceLinkStatus open;
    ASSERT_TRUE(wait_status(link, &scene.world, [](const DeviceLinkStatus& s) {
      return s.capabilities.protocol_version != 0 && s.frames_ok >= 2;
    }, &open)) << rate;
    EXPECT_DOUBLE_EQ(open.input_rate_hz, rate) << "not the announced 100";

    ASSERT_TRUE(press(scene.world, firmware)) << rate;
    DeviceLinkStatus pressing;
    ASSERT_TRUE(wait_status(link, &scene.world, braking, &pressing)) << rate << "; " << describe_hand(scene.world);
    EXPECT_DOUBLE_EQ(pressing.input_rate_hz, rate);
    EXPECT_EQ(pressing.frames_corrupt + pressing.frames_truncated + pressing.frames_out_of_range, 0);
    EXPECT_TRUE(wait_until(scene.world, [&] {
      const auto commands = firmware.commands();
      return !commands.empty() && commands.back().command.command.finger_resistance[kIndex] > 0.0;
    })) << rate;
  }
}

// One stall: the command drops to zero for `reason` and the glove reads the zero; the
// stall is one trip however many commands it holds at zero (while it lasts no command
// goes out with the watchdog clear, so the count cannot move). `reading`: the world the
// host reads meanwhile (none: the host stopped). `ready`: what else the first status
// must show.
void expect_held(DeviceLink& link, World* reading, const SimulatedGlove& glove, WatchdogReason reason,
                 int64_t trips_before, const std::function<bool(const DeviceLinkStatus&)>& ready = nullptr) {
  DeviceLinkStatus first, later;
  ASSERT_TRUE(wait_status(link, reading, [&](const DeviceLinkStatus& s) {
    return s.watchdog == reason && all_zero(s.last_command) && (!ready || ready(s));
  }, &first)) << "reason " << static_cast<int>(reason) << ", now " << static_cast<int>(link.status().watchdog);
  ASSERT_TRUE(wait(reading, [&] { return last_brakes(glove)[kIndex] == 0; }));
  ASSERT_TRUE(wait_status(link, reading, [&](const DeviceLinkStatus& s) {
    return s.commands_sent >= first.commands_sent + 10;
  }, &later));
  EXPECT_GT(first.watchdog_trips, trips_before) << static_cast<int>(reason);
  EXPECT_NE(later.watchdog, WatchdogReason::kNone);
  EXPECT_EQ(later.watchdog_trips, first.watchdog_trips) << "one trip per stall: " << static_cast<int>(reason);
}

TEST(deviceLink, FrozenGloveStoppedEngineAndAbsentHostReleaseTheGlove) {
  Scene scene;
  OpenGlovesFirmware firmware;
  SimulatedGlove glove(temp_path("glove"), 100.0, firmware.firmware());
  auto link = open_link(scene.world, glove.path());
  ASSERT_TRUE(press(scene.world, firmware, *link, glove));
  // braking again, as the glove reads it and the status says
  const auto resumed = [&](DeviceLinkStatus* s) {
    return wait_status(*link, &scene.world, braking, s) &&
           wait_until(scene.world, [&] { return last_brakes(glove)[kIndex] > 0; });
  };
  DeviceLinkStatus s;
  ASSERT_TRUE(resumed(&s));

  // the glove freezes: once the link has taken every frame it sent, none can come
  glove.set_sending(false);
  expect_held(*link, &scene.world, glove, WatchdogReason::kInputStalled, s.watchdog_trips,
              [&](const DeviceLinkStatus& t) { return t.frames_ok == glove.frames_sent(); });
  glove.set_sending(true);
  ASSERT_TRUE(resumed(&s));

  scene.world.stop();
  expect_held(*link, &scene.world, glove, WatchdogReason::kEngineStalled, s.watchdog_trips);
  ASSERT_EQ(scene.world.start(), FRUSTA_OK);
  ASSERT_TRUE(resumed(&s));

  // the host stops reading the world (and the waits above stop reading it too)
  expect_held(*link, nullptr, glove, WatchdogReason::kHostStalled, s.watchdog_trips);
  ASSERT_TRUE(resumed(&s));
}

TEST(deviceLink, NoDeviceNoThread) {
  const int base = thread_count();
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  world.step();
  EXPECT_EQ(thread_count(), base) << "a world without its own thread or a glove runs none";
  OpenGlovesFirmware firmware;
  SimulatedGlove glove(temp_path("glove"), 100.0, firmware.firmware());
  const int with_glove = thread_count();  // the simulated glove's own thread
  {
    auto link = open_link(world, glove.path());
    EXPECT_EQ(thread_count(), with_glove + 1);
    link->close();
    EXPECT_TRUE(thread_count_becomes(with_glove)) << thread_count();
  }
  // a glove that is not there is an error at open, and leaves no thread behind
  DeviceLink missing(world.port(0), DeviceLinkDef{}, std::make_unique<SerialStream>(temp_path("none"), 115200),
                     std::make_unique<OpenGlovesProtocol>(default_glove_calibration()));
  EXPECT_EQ(missing.open(), FRUSTA_ERROR_IO);
  EXPECT_EQ(thread_count(), with_glove);
}

// When a recording's last record is due, seconds after the recording began.
double recording_seconds(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  size_t at = static_cast<size_t>(std::find(bytes.begin(), bytes.end(), '\n') - bytes.begin()) + 1;
  int64_t last_ns = 0;
  for (; at + 12 <= bytes.size(); at += 12 + (bytes[at + 8] | bytes[at + 9] << 8 | bytes[at + 10] << 16)) {
    last_ns = 0;
    for (int i = 7; i >= 0; --i) last_ns = last_ns << 8 | bytes[at + static_cast<size_t>(i)];
  }
  return static_cast<double>(last_ns) / 1e9;
}

TEST(deviceLink, ARecordingReplaysTheSameHand) {
  const std::string recording = temp_path("recording.bin");
  int64_t live_frames = 0;
  double live_flexion = 0.0;
  {
    Scene scene;
    SimulatedGlove glove(temp_path("glove"), 100.0, [&](int64_t t) {
      return "A0B" + std::to_string(std::min<int64_t>(t * 40, 4000)) + "C0D0E0\n";
    });
    DeviceLinkDef def;
    def.record_path = recording;
    auto link = open_link(scene.world, glove.path(), def);
    ASSERT_TRUE(wait_until(scene.world, [&] { return link->status().frames_ok >= 60; }));
    // the glove stops; the link takes (and records) every frame it sent, then closes
    glove.set_sending(false);
    ASSERT_TRUE(wait_until(scene.world, [&] { return link->status().frames_ok == glove.frames_sent(); }));
    link->close();
    live_frames = link->status().frames_ok;
    // the hand settles on the glove's last frame
    const double last = curl_flexion(std::min<int64_t>((glove.frames_sent() - 1) * 40, 4000));
    ASSERT_TRUE(wait_until(scene.world, [&] { return std::fabs(index_flexion(scene.world) - last) < 1e-9; }))
        << index_flexion(scene.world) << " for " << last;
    live_flexion = index_flexion(scene.world);
  }
  std::string protocol;
  ASSERT_EQ(read_recording_protocol(recording, &protocol), FRUSTA_OK);
  EXPECT_EQ(protocol, "opengloves");
  const double duration = recording_seconds(recording);
  EXPECT_GT(duration, 0.0);
  for (bool real_time : {true, false}) {
    Scene scene;
    DeviceLinkDef def;
    def.reconnect_interval_s = 10.0;  // the end of the recording is the end
    DeviceLink link(scene.world.port(0), def, std::make_unique<ReplayStream>(recording, real_time, false),
                    std::make_unique<OpenGlovesProtocol>(default_glove_calibration()));
    const int64_t start = steady_ns();
    ASSERT_EQ(link.open(), FRUSTA_OK);
    DeviceLinkStatus ended;
    ASSERT_TRUE(wait_status(link, &scene.world, [](const DeviceLinkStatus& s) {
      return s.state == LinkState::kDisconnected;
    }, &ended));
    const double seconds = static_cast<double>(steady_ns() - start) / 1e9;
    EXPECT_EQ(ended.frames_ok, live_frames) << real_time;
    EXPECT_TRUE(wait_until(scene.world, [&] { return std::fabs(index_flexion(scene.world) - live_flexion) < 1e-9; }))
        << real_time;
    EXPECT_DOUBLE_EQ(index_flexion(scene.world), live_flexion) << real_time;
    // in real time each record is played when it is due, so the last not before its time
    // (as fast as read, a replay does not wait: recording_test shows it record by record)
    if (real_time) {
      EXPECT_GE(seconds, duration);
    }
  }
  std::remove(recording.c_str());
}

}  // namespace
}  // namespace frusta
