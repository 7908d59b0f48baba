// SPDX-License-Identifier: MIT
// Our binary profile both ways (binary_profile.md): the CRC against its published
// check value, every message through the glove's encoders and the host's decoder in
// any chunking, and a line that corrupts, cuts and pads frames with noise.
#include "devices/frusta_protocol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "collecting_sink.h"

namespace frusta {
namespace {

namespace bp = binary_profile;

constexpr double kPi = 3.14159265358979323846;

void feed(FrustaProtocol& host, const std::vector<uint8_t>& bytes, Collect* sink) {
  host.feed(bytes.data(), bytes.size(), sink);
}

// a glove answering the handshake: CAPS for a 1 kHz fingertip-force glove with a tracker
DeviceCapabilities force_glove() {
  DeviceCapabilities caps;
  caps.outputs = kOutputFingertipForce | kOutputFingerResistance;
  caps.has_palm_pose = true;
  caps.max_finger_resistance = 20.0;
  caps.max_fingertip_force = 8.5;
  caps.max_joint_torque = 0.0;
  caps.input_rate_hz = 1000.0;
  caps.output_rate_hz = 500.0;
  return caps;
}

DeviceSample random_sample(std::mt19937_64& rng, bool with_palm) {
  std::uniform_real_distribution<double> angle(-kPi, kPi), coordinate(-5.0, 5.0), unit(-1.0, 1.0);
  DeviceSample s;
  for (double& a : s.angles) a = angle(rng);
  s.has_palm_pose = with_palm;
  if (with_palm) {
    s.palm_position = vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    s.palm_rotation = glm::normalize(glm::dquat(unit(rng), unit(rng), unit(rng), unit(rng)));
  }
  return s;
}

// what quantisation may change: half a count
void expect_same_sample(const DeviceSample& got, const DeviceSample& sent) {
  for (size_t j = 0; j < sent.angles.size(); ++j)
    EXPECT_NEAR(got.angles[j], sent.angles[j], 0.5 * bp::kAngleUnit + 1e-12) << j;
  ASSERT_EQ(got.has_palm_pose, sent.has_palm_pose);
  if (!sent.has_palm_pose) return;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(got.palm_position[i], sent.palm_position[i], 0.5 * bp::kPositionUnit + 1e-12);
  // same rotation (q and -q are one), to the quantisation of a component
  EXPECT_GT(std::fabs(glm::dot(got.palm_rotation, sent.palm_rotation)), 1.0 - 1e-8);
}

TEST(binaryProfile, CrcIsCcittFalse) {
  const uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(bp::crc16(check, sizeof check), 0x29B1);  // the catalogue's check value
  EXPECT_EQ(bp::crc16(nullptr, 0), 0xFFFF);
}

TEST(binaryProfile, HandshakeThenHeartbeatsAndTheGloveReadsTheHello) {
  FrustaProtocol host(1000, 500);
  std::vector<uint8_t> wire;
  host.start(&wire);
  wire.clear();
  host.encode_heartbeat(&wire);  // no CAPS yet: the HELLO again

  struct Glove final : bp::HostSink {
    std::vector<bp::Hello> hellos;
    int heartbeats = 0, faults = 0;
    void on_hello(const bp::Hello& h) override { hellos.push_back(h); }
    void on_command(const bp::Command&) override {}
    void on_heartbeat() override { ++heartbeats; }
    void on_fault(FrameFault) override { ++faults; }
  } glove;
  bp::GloveSideDecoder decoder;
  decoder.feed(wire.data(), wire.size(), &glove);
  ASSERT_EQ(glove.hellos.size(), 1u);
  EXPECT_EQ(glove.hellos[0].version, bp::kVersion);
  EXPECT_EQ(glove.hellos[0].sample_rate_hz, 1000);
  EXPECT_EQ(glove.hellos[0].command_rate_hz, 500);

  std::vector<uint8_t> reply;
  bp::encode_caps(force_glove(), &reply);
  Collect sink;
  feed(host, reply, &sink);
  ASSERT_EQ(sink.capabilities.size(), 1u);
  const DeviceCapabilities& caps = sink.capabilities[0];
  EXPECT_EQ(caps.protocol_version, bp::kVersion);
  EXPECT_EQ(caps.outputs, kOutputFingertipForce | kOutputFingerResistance);
  EXPECT_TRUE(caps.has_palm_pose);
  EXPECT_DOUBLE_EQ(caps.max_finger_resistance, 20.0);
  EXPECT_DOUBLE_EQ(caps.max_fingertip_force, 8.5);
  EXPECT_DOUBLE_EQ(caps.input_rate_hz, 1000.0);
  EXPECT_DOUBLE_EQ(caps.output_rate_hz, 500.0);

  wire.clear();
  host.encode_heartbeat(&wire);  // answered: a plain HEARTBEAT now
  decoder.feed(wire.data(), wire.size(), &glove);
  EXPECT_EQ(glove.hellos.size(), 1u);
  EXPECT_EQ(glove.heartbeats, 1);
  EXPECT_EQ(glove.faults, 0);
}

TEST(binaryProfile, SamplesSurviveAnyChunkingToHalfACount) {
  std::mt19937_64 rng(7);
  std::vector<DeviceSample> sent;
  std::vector<uint8_t> wire;
  for (int i = 0; i < 300; ++i) {
    sent.push_back(random_sample(rng, i % 3 != 0));
    sent.back().device_time_us = 1000 * i;
    bp::encode_sample(sent.back(), static_cast<uint16_t>(i), &wire);
    if (i % 50 == 0) bp::encode_heartbeat(&wire);
  }
  for (size_t max_chunk : {size_t{1}, size_t{2}, size_t{7}, size_t{64}, size_t{100000}}) {
    FrustaProtocol host;
    std::vector<uint8_t> start;
    host.start(&start);
    Collect sink;
    std::uniform_int_distribution<size_t> chunk(1, max_chunk);
    for (size_t at = 0; at < wire.size();) {
      const size_t n = std::min(chunk(rng), wire.size() - at);
      host.feed(wire.data() + at, n, &sink);
      at += n;
    }
    ASSERT_EQ(sink.samples.size(), sent.size()) << "chunks up to " << max_chunk;
    EXPECT_EQ(sink.heartbeats, 6);
    EXPECT_EQ(sink.corrupt + sink.truncated + sink.out_of_range, 0);
    for (size_t i = 0; i < sent.size(); ++i) {
      expect_same_sample(sink.samples[i], sent[i]);
      EXPECT_EQ(sink.samples[i].device_time_us, sent[i].device_time_us);
    }
  }
}

TEST(binaryProfile, CommandsCarryTheAnnouncedOutputsToTheirUnits) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> force(0.0, 10.0), signed_force(-10.0, 10.0),
      torque(-0.5, 0.5);
  FrustaProtocol host;
  std::vector<uint8_t> wire;
  host.start(&wire);
  struct Glove final : bp::HostSink {
    std::vector<bp::Command> commands;
    int faults = 0;
    void on_hello(const bp::Hello&) override {}
    void on_command(const bp::Command& c) override { commands.push_back(c); }
    void on_heartbeat() override {}
    void on_fault(FrameFault) override { ++faults; }
  } glove;
  bp::GloveSideDecoder decoder;
  const uint32_t all = kOutputFingerResistance | kOutputFingertipForce | kOutputJointTorque;
  for (uint32_t outputs = 0; outputs <= all; ++outputs) {
    DeviceCapabilities caps;
    caps.outputs = outputs;
    DeviceCommand c;
    for (double& r : c.finger_resistance) r = force(rng);
    for (vec3& f : c.fingertip_force) f = vec3(signed_force(rng), signed_force(rng), signed_force(rng));
    for (double& t : c.joint_torque) t = torque(rng);
    wire.clear();
    host.encode(c, caps, &wire);
    if (outputs == 0) {
      EXPECT_TRUE(wire.empty()) << "a glove that renders nothing is sent no commands";
      continue;
    }
    const size_t before = glove.commands.size();
    decoder.feed(wire.data(), wire.size(), &glove);
    ASSERT_EQ(glove.commands.size(), before + 1) << outputs;
    const bp::Command& got = glove.commands.back();
    EXPECT_EQ(got.outputs, outputs);
    EXPECT_EQ(got.sequence, static_cast<uint16_t>(outputs - 1));
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      const bool r = outputs & kOutputFingerResistance, t = outputs & kOutputFingertipForce;
      EXPECT_NEAR(got.command.finger_resistance[f], r ? c.finger_resistance[f] : 0.0,
                  0.5 * bp::kForceUnit + 1e-12);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(got.command.fingertip_force[f][i], t ? c.fingertip_force[f][i] : 0.0,
                    0.5 * bp::kForceUnit + 1e-12);
    }
    for (size_t j = 0; j < c.joint_torque.size(); ++j)
      EXPECT_NEAR(got.command.joint_torque[j], outputs & kOutputJointTorque ? c.joint_torque[j] : 0.0,
                  0.5 * bp::kTorqueUnit + 1e-12);
  }
  EXPECT_EQ(glove.faults, 0);
}

TEST(binaryProfile, ImpossibleValuesAreOutOfRangeNotSamples) {
  Collect sink;
  FrustaProtocol host;
  std::vector<uint8_t> wire;
  host.start(&wire);
  DeviceSample nan_angle;
  nan_angle.angles[5] = std::nan("");  // goes out as the field's most negative value
  DeviceSample beyond_pi;
  beyond_pi.angles[9] = 3.2;
  DeviceSample far_palm;
  far_palm.has_palm_pose = true;
  far_palm.palm_position = vec3(0.0, 2000.0, 0.0);  // 2 km
  DeviceSample nan_palm;
  nan_palm.has_palm_pose = true;
  nan_palm.palm_rotation = glm::dquat(std::nan(""), 0.0, 0.0, 0.0);
  wire.clear();
  for (const DeviceSample& s : {nan_angle, beyond_pi, far_palm, nan_palm}) bp::encode_sample(s, 0, &wire);
  DeviceCapabilities from_the_future;
  from_the_future.protocol_version = 0x0200;  // a major version we do not speak
  bp::encode_caps(from_the_future, &wire);
  bp::encode_sample(DeviceSample{}, 1, &wire);
  feed(host, wire, &sink);
  EXPECT_EQ(sink.out_of_range, 5);
  EXPECT_TRUE(sink.capabilities.empty());
  ASSERT_EQ(sink.samples.size(), 1u) << "the good sample after them";
  EXPECT_EQ(sink.corrupt + sink.truncated, 0);
}

// The palm's field reaches 1 km as it counts (10^8 counts of 10 um, a rounding over 1 km
// in metres: the glove fuzzer's second finding), and no count further.
TEST(binaryProfile, APalmAtTheFieldsEdgeIsASampleAndOneCountBeyondIsNot) {
  Collect sink;
  FrustaProtocol host;
  std::vector<uint8_t> wire;
  host.start(&wire);
  wire.clear();
  const double edge = bp::kMaxPositionCounts * bp::kPositionUnit;
  DeviceSample at_edge;
  at_edge.has_palm_pose = true;
  at_edge.palm_position = vec3(edge, -edge, 0.0);
  DeviceSample beyond = at_edge;
  beyond.palm_position.z = -(bp::kMaxPositionCounts + 1) * bp::kPositionUnit;
  bp::encode_sample(at_edge, 0, &wire);
  bp::encode_sample(beyond, 1, &wire);
  feed(host, wire, &sink);
  ASSERT_EQ(sink.samples.size(), 1u);
  EXPECT_EQ(sink.samples[0].palm_position, at_edge.palm_position);
  EXPECT_EQ(sink.out_of_range, 1);
}

// A line that flips bits, cuts frames short and adds noise loses exactly the frames it
// touched, reports each once, and never hands on a damaged one.
TEST(binaryProfile, CorruptCutAndNoisyFramesAreDroppedAndTheRestKept) {
  std::mt19937_64 rng(3);
  std::vector<uint8_t> wire;
  std::vector<DeviceSample> kept;
  int flipped = 0, cut = 0;
  std::uniform_int_distribution<int> what(0, 9), noise_byte(0, 255);
  bool damaged = false;
  for (int i = 0; i < 2000; ++i) {
    DeviceSample s = random_sample(rng, i % 2 == 0);
    std::vector<uint8_t> frame;
    bp::encode_sample(s, static_cast<uint16_t>(i), &frame);
    // a good frame after each damaged one, so each damage is a fault of its own
    const int w = damaged ? 9 : what(rng);
    damaged = w <= 1;
    if (w == 0) {  // a bit flipped in the payload or CRC (a flipped header is a
                   // different frame, whose own payload bytes then get scanned)
      std::uniform_int_distribution<size_t> at(bp::kHeaderSize, frame.size() - 1);
      frame[at(rng)] ^= static_cast<uint8_t>(1u << (i % 8));
      ++flipped;
    } else if (w == 1) {  // the glove reset mid-frame: the rest never comes
      frame.resize(frame.size() / 2);
      ++cut;
    } else {
      kept.push_back(s);
    }
    wire.insert(wire.end(), frame.begin(), frame.end());
    if (w == 2)  // line noise between frames, without sync bytes
      for (int n = 0; n < 5; ++n) wire.push_back(static_cast<uint8_t>(noise_byte(rng) % 0xF0));
  }
  FrustaProtocol host;
  std::vector<uint8_t> start;
  host.start(&start);
  Collect sink;
  feed(host, wire, &sink);
  ASSERT_EQ(sink.samples.size(), kept.size());
  for (size_t i = 0; i < kept.size(); ++i) expect_same_sample(sink.samples[i], kept[i]);
  EXPECT_GT(flipped, 100);
  EXPECT_GT(cut, 100);
  EXPECT_EQ(sink.corrupt, flipped);
  EXPECT_EQ(sink.truncated, cut) << "a good frame began inside each cut one";
  EXPECT_EQ(sink.out_of_range, 0);
}

TEST(binaryProfile, TheGlovesClockIsUnwrappedAcrossItsTurn) {
  FrustaProtocol host;
  std::vector<uint8_t> wire;
  host.start(&wire);
  wire.clear();
  const int64_t turn = int64_t{1} << 32;
  const int64_t times[] = {turn - 2000, turn - 1000, turn, turn + 1000, 2 * turn + 5};
  for (int64_t t : times) {
    DeviceSample s;
    s.device_time_us = t;
    bp::encode_sample(s, 0, &wire);
  }
  Collect sink;
  feed(host, wire, &sink);
  ASSERT_EQ(sink.samples.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(sink.samples[i].device_time_us, times[i]) << i;
}

TEST(binaryProfile, TheSampleSequenceIsUnwrappedAcrossItsTurn) {
  FrustaProtocol host;
  std::vector<uint8_t> wire;
  host.start(&wire);
  wire.clear();
  const int64_t sequences[] = {65533, 65535, 65536 + 2, 65536 + 40000, 2 * 65536 + 1};
  for (int64_t n : sequences) bp::encode_sample(DeviceSample{}, static_cast<uint16_t>(n), &wire);
  Collect sink;
  feed(host, wire, &sink);
  ASSERT_EQ(sink.samples.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(sink.samples[i].sequence, sequences[i]) << i;
}

}  // namespace
}  // namespace frusta
