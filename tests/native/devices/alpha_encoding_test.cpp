// SPDX-License-Identifier: MIT
// The OpenGloves alpha encoding both ways, the calibration from raw units to joint
// angles and brake units, and the protocol that joins them.
#include "devices/alpha_encoding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "collecting_sink.h"
#include "devices/glove_calibration.h"
#include "devices/opengloves_protocol.h"

namespace frusta {
namespace {

constexpr double kMax = 4095.0;

void feed(OpenGlovesProtocol& p, const std::string& bytes, Collect* sink) {
  p.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), sink);
}

TEST(alphaEncoding, DecodesAWholeFingerLucidGlovesLine) {
  // what LucidGloves firmware sends: five curls, joystick, buttons (trigger and A held)
  RawGloveReading r;
  ASSERT_EQ(decode_alpha_line("A0B1024C2048D3072E4095F2048G2048IJ", kMax, &r), AlphaLine::kSample);
  const double expected[5] = {0, 1024, 2048, 3072, 4095};
  for (int f = 0; f < 5; ++f) {
    EXPECT_TRUE(r.has_curl[f]);
    EXPECT_FALSE(r.has_splay[f]);
    for (int j = 0; j < 3; ++j) EXPECT_EQ(r.curl[f][j], expected[f]) << f << " " << j;
  }
}

TEST(alphaEncoding, JointsOverrideTheFingerAndFingersSkipTheMetacarpal) {
  RawGloveReading r;
  // index: finger curl 100, wire joints 1..3 = 200, 300, 400 (joint 0 is the metacarpal);
  // thumb: only wire joint 2, so its other joints take the nearest reported one
  ASSERT_EQ(decode_alpha_line("B100(BAA)999(BAB)200(BAC)300(BAD)400(AAC)50(CB)3000\r", kMax, &r),
            AlphaLine::kSample);
  EXPECT_EQ(r.curl[1][0], 200);
  EXPECT_EQ(r.curl[1][1], 300);
  EXPECT_EQ(r.curl[1][2], 400);
  EXPECT_EQ(r.curl[0][0], 50);
  EXPECT_EQ(r.curl[0][2], 50);
  EXPECT_TRUE(r.has_curl[0]);
  EXPECT_FALSE(r.has_curl[2]);
  EXPECT_TRUE(r.has_splay[2]);
  EXPECT_EQ(r.splay[2], 3000);
}

TEST(alphaEncoding, ClassifiesBadLines) {
  RawGloveReading r;
  EXPECT_EQ(decode_alpha_line("", kMax, &r), AlphaLine::kNoFingers);
  EXPECT_EQ(decode_alpha_line("F100G200HIJ(ZV)3", kMax, &r), AlphaLine::kNoFingers);
  EXPECT_EQ(decode_alpha_line("95B100C100", kMax, &r), AlphaLine::kTruncated);
  EXPECT_EQ(decode_alpha_line("A100b200", kMax, &r), AlphaLine::kCorrupt);
  EXPECT_EQ(decode_alpha_line("A100B", kMax, &r), AlphaLine::kCorrupt);  // finger without value
  EXPECT_EQ(decode_alpha_line("A1(BB", kMax, &r), AlphaLine::kCorrupt);
  EXPECT_EQ(decode_alpha_line("A1 B2", kMax, &r), AlphaLine::kCorrupt);
  EXPECT_EQ(decode_alpha_line("A4096", kMax, &r), AlphaLine::kOutOfRange);
  EXPECT_EQ(decode_alpha_line("A1234567890123", kMax, &r), AlphaLine::kOutOfRange);
  EXPECT_EQ(decode_alpha_line("A4095Q7", kMax, &r), AlphaLine::kSample);  // a newer key is skipped
}

TEST(alphaEncoding, InputRoundTripsThroughTheGlovesSide) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 4095);
  for (int trial = 0; trial < 1000; ++trial) {
    RawGloveReading in;
    for (int f = 0; f < 5; ++f) {
      in.has_curl[f] = true;
      in.has_splay[f] = trial % 2 == 0;
      in.splay[f] = value(rng);
      for (int j = 0; j < 3; ++j) in.curl[f][j] = value(rng);
    }
    char line[256];
    const size_t n = encode_alpha_input(in, true, line, sizeof line);
    ASSERT_GT(n, 0u);
    ASSERT_EQ(line[n - 1], '\n');
    RawGloveReading out;
    ASSERT_EQ(decode_alpha_line(std::string_view(line, n - 1), kMax, &out), AlphaLine::kSample);
    for (int f = 0; f < 5; ++f) {
      EXPECT_EQ(out.has_splay[f], in.has_splay[f]);
      if (in.has_splay[f]) {
        EXPECT_EQ(out.splay[f], in.splay[f]);
      }
      for (int j = 0; j < 3; ++j) EXPECT_EQ(out.curl[f][j], in.curl[f][j]);
    }
  }
}

TEST(alphaEncoding, BrakesRoundTripAndClamp) {
  char line[40];
  const size_t n = encode_alpha_brakes({0, 250, 1000, -5, 12345}, line, sizeof line);
  EXPECT_EQ(std::string(line, n), "A0B250C1000D0E9999\n");
  std::array<int32_t, 5> units{};
  ASSERT_TRUE(decode_alpha_brakes(std::string_view(line, n), &units));
  EXPECT_EQ(units, (std::array<int32_t, 5>{0, 250, 1000, 0, 9999}));
  EXPECT_FALSE(decode_alpha_brakes("A1B2C3D4", &units));  // no little finger
  EXPECT_EQ(encode_alpha_brakes({1, 2, 3, 4, 5}, line, 8), 0u);  // too small: nothing
}

TEST(gloveCalibration, MapsRawUnitsToAnglesAndHoldsTheEnds) {
  const GloveCalibration c = default_glove_calibration();
  ASSERT_EQ(check_glove_calibration(c), FRUSTA_OK);
  RawGloveReading raw;
  raw.has_curl = {true, true, true, true, true};
  raw.has_splay = {false, true, false, false, false};
  for (int f = 0; f < 5; ++f) raw.curl[f] = {4095.0 / 2, 4095.0 / 2, 4095.0 / 2};
  raw.curl[2] = {-100.0, 5000.0, 4095.0};  // beyond both ends: held at them
  raw.splay[1] = 2048.0 + 2047.0;          // full splay one way
  std::array<double, FRUSTA_HAND_JOINT_COUNT> previous{}, angles{};
  previous[0] = 0.3;  // the thumb's abduction: not reported, so kept
  raw_to_joint_angles(c, raw, previous, &angles);
  EXPECT_DOUBLE_EQ(angles[0], 0.3);
  EXPECT_NEAR(angles[1 * 4 + 0], c.abduction_range[1], 1e-12);
  EXPECT_NEAR(angles[1 * 4 + 2], c.flexion_closed[1][1] / 2, 1e-12);
  EXPECT_DOUBLE_EQ(angles[2 * 4 + 1], c.flexion_open[2][0]);
  EXPECT_DOUBLE_EQ(angles[2 * 4 + 2], c.flexion_closed[2][1]);
  EXPECT_DOUBLE_EQ(angles[2 * 4 + 3], c.flexion_closed[2][2]);
}

TEST(gloveCalibration, BrakeUnitsAreProportionalAndSafe) {
  const GloveCalibration c = default_glove_calibration();  // 10 N = 1000 units
  EXPECT_EQ(resistance_to_brake_units(c, 0.0), 0);
  EXPECT_EQ(resistance_to_brake_units(c, 2.5), 250);
  EXPECT_EQ(resistance_to_brake_units(c, 10.0), 1000);
  EXPECT_EQ(resistance_to_brake_units(c, 1e9), 1000);
  EXPECT_EQ(resistance_to_brake_units(c, -3.0), 0);
  EXPECT_EQ(resistance_to_brake_units(c, std::nan("")), 0);
}

TEST(gloveCalibration, RefusesWhatCannotBeAMapping) {
  GloveCalibration c = default_glove_calibration();
  c.curl_closed[3][1] = c.curl_open[3][1];
  EXPECT_EQ(check_glove_calibration(c), FRUSTA_ERROR_OUT_OF_RANGE);
  c = default_glove_calibration();
  c.flexion_closed[0][0] = std::nan("");
  EXPECT_EQ(check_glove_calibration(c), FRUSTA_ERROR_NOT_FINITE);
  c = default_glove_calibration();
  c.brake_full_scale = 0.0;
  EXPECT_EQ(check_glove_calibration(c), FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST(openGlovesProtocol, SplitsLinesAnywhereAndCountsFaults) {
  OpenGlovesProtocol p(default_glove_calibration());
  Collect sink;
  std::vector<uint8_t> hello;
  p.start(&hello);
  EXPECT_TRUE(hello.empty());  // no handshake in this encoding
  const std::string stream =
      "A0B0C0D0E0\n"               // open hand
      "A4095B4095C4095D4095E4095\n"  // fist
      "095C4095\n"                 // joined mid-line
      "A1x\n"                      // corrupt
      "A9999\n"                    // beyond the ADC
      "IJ\n"                       // buttons only
      + std::string(300, 'A') + "\n"  // no newline for too long
      + "B2048\n";
  for (size_t i = 0; i < stream.size(); ++i) feed(p, stream.substr(i, 1), &sink);  // byte by byte
  ASSERT_EQ(sink.samples.size(), 3u);
  EXPECT_EQ(sink.truncated, 2);
  EXPECT_EQ(sink.corrupt, 1);
  EXPECT_EQ(sink.out_of_range, 1);
  EXPECT_EQ(sink.heartbeats, 1);
  const GloveCalibration c = default_glove_calibration();
  EXPECT_DOUBLE_EQ(sink.samples[0].angles[1 * 4 + 1], 0.0);
  EXPECT_DOUBLE_EQ(sink.samples[1].angles[1 * 4 + 1], c.flexion_closed[1][0]);
  // only the index came: the other fingers stay in the fist
  EXPECT_NEAR(sink.samples[2].angles[1 * 4 + 1], c.flexion_closed[1][0] * 2048 / 4095, 1e-12);
  EXPECT_DOUBLE_EQ(sink.samples[2].angles[2 * 4 + 1], c.flexion_closed[2][0]);
}

TEST(openGlovesProtocol, EncodesResistanceAsBrakesOnlyForAGloveWithBrakes) {
  OpenGlovesProtocol p(default_glove_calibration());
  DeviceCommand command;
  command.finger_resistance = {0.0, 5.0, 10.0, 20.0, 0.1};
  std::vector<uint8_t> out;
  DeviceCapabilities caps = p.default_capabilities();
  p.encode(command, caps, &out);
  EXPECT_EQ(std::string(out.begin(), out.end()), "A0B500C1000D1000E10\n");
  out.clear();
  caps.outputs = kOutputFingertipForce;
  p.encode(command, caps, &out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace frusta
