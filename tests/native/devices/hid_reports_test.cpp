// SPDX-License-Identifier: MIT
// Our binary profile over HID reports: the report packing both ways, and hidapi's real
// backend (hidraw on Linux, the Windows one on Windows) asked for a glove that is not
// there. A glove that is there: hid_uhid_test.cpp.
#include "devices/hid_stream.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "collecting_sink.h"
#include "core/error.h"
#include "devices/frusta_protocol.h"

namespace frusta {
namespace {

namespace bp = binary_profile;
constexpr uint16_t kVendor = 0x1209, kProduct = 0xF5F5;  // pid.codes' test range

TEST(hidReports, FramesSplitIntoReportsAndJoinAgain) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::vector<uint8_t> stream;
  std::vector<DeviceSample> sent(40);
  for (size_t i = 0; i < sent.size(); ++i) {
    for (double& a : sent[i].angles) a = angle(rng);
    bp::encode_sample(sent[i], static_cast<uint16_t>(i), &stream);
  }
  std::vector<std::vector<uint8_t>> reports;
  for (size_t at = 0; at < stream.size();) {
    std::vector<uint8_t> report(hid_reports::kReportSize, 0xAA);
    at += hid_reports::pack(stream.data() + at, stream.size() - at, report.data());
    reports.push_back(report);
  }
  EXPECT_EQ(reports.size(), (stream.size() + hid_reports::kMaxChunk - 1) / hid_reports::kMaxChunk);
  EXPECT_EQ(reports.back()[hid_reports::kReportSize - 1], 0) << "padding is zeros";

  FrustaProtocol host;
  std::vector<uint8_t> hello;
  host.start(&hello);
  Collect sink;
  for (const std::vector<uint8_t>& report : reports) {
    const uint8_t* bytes = nullptr;
    size_t count = 0;
    ASSERT_TRUE(hid_reports::unpack(report.data(), report.size(), &bytes, &count));
    host.feed(bytes, count, &sink);
  }
  ASSERT_EQ(sink.samples.size(), sent.size());
  for (size_t i = 0; i < sent.size(); ++i)
    EXPECT_NEAR(sink.samples[i].angles[7], sent[i].angles[7], 0.5 * bp::kAngleUnit + 1e-12);
}

TEST(hidReports, AReportClaimingMoreThanItHoldsIsDropped) {
  uint8_t report[hid_reports::kReportSize] = {};
  const uint8_t* bytes = nullptr;
  size_t count = 0;
  report[0] = 63;
  EXPECT_TRUE(hid_reports::unpack(report, 64, &bytes, &count));
  EXPECT_EQ(count, 63u);
  EXPECT_FALSE(hid_reports::unpack(report, 40, &bytes, &count)) << "a short read";
  report[0] = 64;
  EXPECT_FALSE(hid_reports::unpack(report, 64, &bytes, &count));
  EXPECT_FALSE(hid_reports::unpack(report, 0, &bytes, &count));
}

TEST(hidStream, AnAbsentGloveIsAnIoErrorNamingIt) {
  HidStream stream(kVendor, kProduct, "FR-0042");
  EXPECT_EQ(stream.open(), FRUSTA_ERROR_IO);  // through hidapi's backend
  EXPECT_NE(std::strstr(frusta::last_error_message(), "hid 1209:f5f5:FR-0042: cannot open"), nullptr)
      << frusta::last_error_message();
  EXPECT_FALSE(stream.is_open());
  uint8_t buffer[64];
  size_t received = 1;
  EXPECT_EQ(stream.read(buffer, sizeof buffer, 1000, &received), IoStatus::kDisconnected);
  EXPECT_EQ(received, 0u);
  bool dropped = true;
  EXPECT_EQ(stream.write(buffer, 10, &dropped), IoStatus::kDisconnected);
  EXPECT_FALSE(dropped);
}

}  // namespace
}  // namespace frusta
