// SPDX-License-Identifier: MIT
// The gloves' C ABI: defs and URIs checked with named fields, a glove on a real pseudo-
// terminal opened by URI, its status, its palm, its hand closed to other input, ids
// turning stale, a world taking its gloves with it, enumeration, record and replay, and
// recordings that are not (a FIFO, /dev/zero, ...) refused by name. Every check waits
// for the state it checks (the deadline only turns a hang into a failure): none holds
// a wall clock against a rate or a count.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "device_api_fixture.h"
#include "scenes/hostile_recordings.h"
#include "scenes/process_probe.h"
#include "scenes/simulated_glove.h"

namespace frusta::testing {
namespace {

using scenes::SimulatedGlove;
using scenes::temp_path;
using scenes::thread_count;
using scenes::thread_count_becomes;
constexpr double kPatience = 120.0;  // seconds: a wait's deadline, which only a hang reaches

SimulatedGlove::Firmware lucidgloves(int index_curl) {
  return [index_curl](int64_t) { return "A0B" + std::to_string(index_curl) + "C0D0E0\n"; };
}

TEST_F(DeviceApiTest, DefaultDefIsAFistGloveWithSafeTimeouts) {
  const frusta_device_def def = frusta_default_device_def();
  EXPECT_EQ(def.struct_size, static_cast<int32_t>(sizeof(frusta_device_def)));
  EXPECT_TRUE(FRUSTA_IS_NULL(def.hand)) << "the caller names the hand";
  EXPECT_EQ(def.reserved1, 0);
  EXPECT_DOUBLE_EQ(def.watchdog_s, 0.05);
  EXPECT_DOUBLE_EQ(def.host_timeout_s, 0.25);
  EXPECT_DOUBLE_EQ(def.curl_closed[1][0], 4095.0);
  EXPECT_NEAR(def.flexion_closed[1][1], 90 * std::acos(-1.0) / 180, 1e-12);
  EXPECT_DOUBLE_EQ(def.brake_units, 1000.0);
}

TEST_F(DeviceApiTest, BadDefsAndUrisAreRefusedByName) {
  frusta_device_id device{};
  frusta_device_def def = device_def();
  def.watchdog_s = 0.0;
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device),
              FRUSTA_ERROR_OUT_OF_RANGE, "watchdog_s");
  def = device_def();
  def.curl_closed[2][1] = def.curl_open[2][1];
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device),
              FRUSTA_ERROR_OUT_OF_RANGE, "fist");
  def = device_def();
  def.hand.index1 = 2;
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device),
              FRUSTA_ERROR_STALE_ID, "frusta_device_def.hand");
  def = frusta_default_device_def();  // no hand named
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device),
              FRUSTA_ERROR_NULL_ID, "frusta_device_def.hand");
  def = device_def();
  def.struct_size -= 8;
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device),
              FRUSTA_ERROR_STRUCT_SIZE, "frusta_device_def");
  def = device_def();
  ExpectError(frusta_create_device(world_, "bluetooth:glove", &def, &device),
              FRUSTA_ERROR_OUT_OF_RANGE, "unknown scheme");
  ExpectError(frusta_create_device(world_, "opengloves:/dev/ttyACM0?baud=12345", &def, &device),
              FRUSTA_ERROR_OUT_OF_RANGE, "baud");
  ExpectError(frusta_create_device(world_, "hid:12g4:1", &def, &device), FRUSTA_ERROR_OUT_OF_RANGE,
              "hexadecimal");
  ExpectError(frusta_create_device(world_, "replay:x?speed=3", &def, &device),
              FRUSTA_ERROR_OUT_OF_RANGE, "speed");
  ExpectError(frusta_create_device(world_, "opengloves:/nonexistent/ttyACM9", &def, &device),
              FRUSTA_ERROR_IO, "/nonexistent/ttyACM9");
  ExpectError(frusta_create_device(world_, "opengloves:/dev/null", &def, &device), FRUSTA_ERROR_IO,
              "not a serial port");
  ExpectError(frusta_create_device(world_, "replay:/nonexistent.rec", &def, &device),
              FRUSTA_ERROR_IO, "/nonexistent.rec");
  ExpectError(frusta_create_device(world_, nullptr, &def, &device), FRUSTA_ERROR_NULL_POINTER,
              "uri");
  EXPECT_TRUE(FRUSTA_IS_NULL(device)) << "a failed open writes no id";
  EXPECT_EQ(frusta_device_is_valid(device), 0);
}

TEST_F(DeviceApiTest, AGloveByUriDrivesItsHandAndReportsItsStatus) {
  const int base = thread_count();
  SimulatedGlove glove(temp_path("glove"), 100.0, lucidgloves(2000));
  const frusta_device_def def = device_def();
  frusta_device_id device{};
  const std::string uri = "opengloves:" + glove.path() + "?baud=115200";
  ASSERT_EQ(frusta_create_device(world_, uri.c_str(), &def, &device), FRUSTA_OK)
      << frusta_last_error();
  EXPECT_EQ(frusta_device_is_valid(device), 1);
  EXPECT_EQ(thread_count(), base + 2) << "the simulated glove's thread and the device's";

  const frusta_pose palm{{0.1, 0.2, 0.3}, {0.0, 0.0, 0.0, 1.0}};
  ASSERT_EQ(frusta_device_set_palm_pose(device, &palm), FRUSTA_OK);
  ASSERT_TRUE(run_until([&] { return status(device).frames_ok > 10; }, kPatience));
  // a step after a sample shows the glove's hand on the palm the host gave
  frusta_world_hand hand{};
  hand.struct_size = sizeof hand;
  const double curled = def.flexion_closed[1][0] * 2000 / 4095;
  EXPECT_TRUE(run_until(
      [&] {
        EXPECT_EQ(frusta_world_get_hand(world_, hand_, &hand), FRUSTA_OK);
        return std::fabs(hand.haptic_palm.position[1] - 0.2) < 1e-12 &&
               std::fabs(hand.haptic_angles[1 * 4 + 1] - curled) < 1e-9;
      },
      kPatience))
      << hand.haptic_palm.position[1] << ", " << hand.haptic_angles[1 * 4 + 1];

  const frusta_device_status s = status(device);
  EXPECT_EQ(s.state, FRUSTA_DEVICE_CONNECTED);
  EXPECT_EQ(s.outputs, FRUSTA_DEVICE_OUTPUT_FINGER_RESISTANCE);
  EXPECT_EQ(s.fingers, 5);
  EXPECT_DOUBLE_EQ(s.output_rate_hz, 100.0);
  EXPECT_DOUBLE_EQ(s.max_finger_resistance, 10.0);
  EXPECT_GT(s.commands_sent, 0);
  EXPECT_GE(s.last_sample_age_s, 0.0);

  // the hand is the glove's now
  const double angles[FRUSTA_HAND_JOINT_COUNT] = {};
  ExpectError(frusta_world_set_haptic(world_, hand_, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_ERROR_WRONG_STATE, "driven by a glove");
  frusta_device_id second{};
  ExpectError(frusta_create_device(world_, uri.c_str(), &def, &second), FRUSTA_ERROR_WRONG_STATE,
              "already has a glove");
  frusta_device_status small{};
  small.struct_size = 16;
  ExpectError(frusta_device_get_status(device, &small), FRUSTA_ERROR_STRUCT_SIZE, "frusta_device_status");

  ASSERT_EQ(frusta_destroy_device(device), FRUSTA_OK);
  EXPECT_EQ(frusta_device_is_valid(device), 0);
  EXPECT_TRUE(thread_count_becomes(base + 1)) << thread_count();
  ExpectError(frusta_destroy_device(device), FRUSTA_ERROR_STALE_ID, "closed");
  ExpectError(frusta_device_get_status(device, &small), FRUSTA_ERROR_STALE_ID, "closed");
  EXPECT_EQ(frusta_world_set_haptic(world_, hand_, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK);
  // the glove got released as the last thing it heard (once its thread has read it)
  const std::string released = "A0B0C0D0E0\n";
  const auto last_line = [&] {
    const std::string heard = glove.received();
    const size_t start = heard.size() < 2 ? std::string::npos : heard.rfind('\n', heard.size() - 2);
    return heard.substr(start == std::string::npos ? 0 : start + 1);
  };
  EXPECT_TRUE(run_until([&] { return last_line() == released; }, kPatience)) << last_line();

  // opened again, the same hand has a new id; destroying the world closes the glove
  ASSERT_EQ(frusta_create_device(world_, uri.c_str(), &def, &second), FRUSTA_OK);
  EXPECT_NE(second.generation, device.generation);
  ASSERT_EQ(frusta_destroy_world(world_), FRUSTA_OK);
  EXPECT_EQ(frusta_device_is_valid(second), 0);
  EXPECT_TRUE(thread_count_becomes(base + 1)) << thread_count();
  ExpectError(frusta_device_get_status(second, &small), FRUSTA_ERROR_STALE_ID, "device");
}

TEST_F(DeviceApiTest, ARecordedGloveReplaysThroughItsUri) {
  const std::string recording = temp_path("recording");
  const frusta_device_def def = device_def();
  const auto curl_at = [](int64_t tick) { return std::min<int64_t>(tick * 30, 4000); };
  frusta_world_hand hand{};
  hand.struct_size = sizeof hand;
  const auto index_angle = [&] {
    EXPECT_EQ(frusta_world_get_hand(world_, hand_, &hand), FRUSTA_OK);
    return hand.haptic_angles[1 * 4 + 1];
  };
  double live_angle = 0.0;
  int64_t live_frames = 0;
  {
    SimulatedGlove glove(temp_path("glove"), 200.0, [&](int64_t t) {
      return "A0B" + std::to_string(curl_at(t)) + "C0D0E0\n";
    });
    frusta_device_id device{};
    const std::string uri = "opengloves:" + glove.path() + "?record=" + recording;
    ASSERT_EQ(frusta_create_device(world_, uri.c_str(), &def, &device), FRUSTA_OK)
        << frusta_last_error();
    ASSERT_TRUE(run_until([&] { return status(device).frames_ok >= 100; }, kPatience));
    // the glove stops; the device takes (and records) every frame it sent, then closes
    glove.set_sending(false);
    live_frames = glove.frames_sent();
    ASSERT_TRUE(run_until([&] { return status(device).frames_ok == live_frames; }, kPatience));
    ASSERT_EQ(frusta_destroy_device(device), FRUSTA_OK);
    // the host's next step takes the glove's last frame
    const double last = def.flexion_closed[1][0] * static_cast<double>(curl_at(live_frames - 1)) / 4095;
    ASSERT_TRUE(run_until([&] { return std::fabs(index_angle() - last) < 1e-9; }, kPatience)) << index_angle();
    live_angle = index_angle();
  }
  frusta_device_id replay{};
  const std::string uri = "replay:" + recording + "?speed=max";
  ASSERT_EQ(frusta_create_device(world_, uri.c_str(), &def, &replay), FRUSTA_OK)
      << frusta_last_error();
  frusta_device_status ended{};
  ASSERT_TRUE(run_until([&] {
    ended = status(replay);
    return ended.state == FRUSTA_DEVICE_DISCONNECTED;
  }, kPatience));
  EXPECT_EQ(ended.frames_ok, live_frames);
  EXPECT_TRUE(run_until([&] { return std::fabs(index_angle() - live_angle) < 1e-9; }, kPatience));
  EXPECT_DOUBLE_EQ(index_angle(), live_angle);
  std::remove(recording.c_str());
}

// What is not a recording, as replay:FILE or &record=FILE, is refused by name, neither
// blocking the open (a FIFO) nor reading without end (/dev/zero, a file too large).
// Each open runs in a child process killed at a deadline or a memory cap, so the old
// hang fails the test instead of hanging it.
TEST_F(DeviceApiTest, WhatIsNotARecordingIsRefusedByName) {
  const scenes::HostileRecordings files(int64_t{1} << 30);
  const frusta_device_def def = device_def();
  const auto open_in_child = [&](const std::string& uri) {
    return scenes::run_in_child([&](std::string* message) {
      frusta_device_id device{};
      const frusta_result r = frusta_create_device(world_, uri.c_str(), &def, &device);
      *message = frusta_last_error();
      return static_cast<int>(r);
    });
  };
  std::vector<std::string> uris;
  std::vector<scenes::HostilePath> expected;
  for (const scenes::HostilePath& h : files.replay) {
    uris.push_back("replay:" + h.path + "?speed=max");
    expected.push_back(h);
  }
  for (const scenes::HostilePath& h : files.record_to) {
    uris.push_back("replay:" + files.good + "?speed=max&record=" + h.path);
    expected.push_back(h);
  }
  for (size_t i = 0; i < uris.size(); ++i) {
    const scenes::ChildOutcome outcome = open_in_child(uris[i]);
    if (!outcome.returned) {
      ADD_FAILURE() << uris[i] << ": " << outcome.message;
      continue;
    }
    EXPECT_EQ(outcome.result, expected[i].code) << uris[i] << ": " << outcome.message;
    EXPECT_NE(outcome.message.find(expected[i].path), std::string::npos) << outcome.message;
    EXPECT_NE(outcome.message.find(expected[i].says), std::string::npos) << outcome.message;
  }
  // and a sound one opens, recording where it may
  const std::string copy = temp_path("copy");
  const std::string uri = "replay:" + files.good + "?speed=max&record=" + copy;
  const scenes::ChildOutcome sound = open_in_child(uri);
  EXPECT_TRUE(sound.returned && sound.result == FRUSTA_OK) << sound.message;
  std::remove(copy.c_str());
}

TEST_F(DeviceApiTest, EnumerationListsWhatIsThereAndReportsTheCount) {
  int32_t count = -1;
  ASSERT_EQ(frusta_enumerate_devices(nullptr, 0, &count), FRUSTA_OK) << frusta_last_error();
  EXPECT_GE(count, 0);
  std::vector<frusta_device_info> infos(static_cast<size_t>(count) + 1);
  int32_t again = -1;
  ASSERT_EQ(frusta_enumerate_devices(infos.data(), static_cast<int32_t>(infos.size()), &again), FRUSTA_OK);
  EXPECT_EQ(again, count);
  for (int32_t i = 0; i < count; ++i) {
    const std::string uri(reinterpret_cast<const char*>(infos[static_cast<size_t>(i)].uri));
    std::printf("  %s\n", uri.c_str());
    EXPECT_TRUE(uri.rfind("serial:", 0) == 0 || uri.rfind("hid:", 0) == 0 || uri.rfind("usb:", 0) == 0) << uri;
  }
  // a buffer with no room still says how many there are
  again = -1;
  ASSERT_EQ(frusta_enumerate_devices(infos.data(), 0, &again), FRUSTA_OK);
  EXPECT_EQ(again, count);
}

}  // namespace
}  // namespace frusta::testing
