// SPDX-License-Identifier: MIT
// Glove recordings: what the recorder writes replays record by record, in real time or
// at once, and so does what it wrote up to its size limit; what is not a recording (a
// FIFO, /dev/zero, a directory, a file too large, a header cut short, garbage, a bad
// record) is refused by name before it can block or be read without end. Each hostile
// open runs in a child process, so a hang or an endless read fails the test (killed at
// a deadline or a memory cap) instead of hanging it or filling the machine.
#include "devices/recording.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "devices/device_factory.h"
#include "devices/device_uri.h"
#include "devices/glove_calibration.h"
#include "scenes/hostile_recordings.h"
#include "scenes/process_probe.h"

namespace frusta {
namespace {

using scenes::temp_path;

int64_t file_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return static_cast<int64_t>(in.tellg());
}

void record(Recorder& recorder, int64_t time_ns, const std::string& bytes) {
  recorder.write(time_ns, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

// A replay's reads with no wait (timeout 0), until it ends or gives nothing now.
std::vector<std::string> read_now(ReplayStream& replay, bool* ended) {
  std::vector<std::string> reads;
  std::vector<uint8_t> buffer(100000);
  *ended = false;
  for (;;) {
    size_t n = 0;
    if (replay.read(buffer.data(), buffer.size(), 0, &n) == IoStatus::kDisconnected) {
      *ended = true;
      return reads;
    }
    if (n == 0) return reads;
    reads.emplace_back(reinterpret_cast<const char*>(buffer.data()), n);
  }
}

TEST(recording, WhatTheRecorderWritesReplaysRecordByRecord) {
  const std::string path = temp_path("recording");
  const std::string big(70000, 'x');  // more than a record holds: two records
  {
    Recorder recorder;
    ASSERT_EQ(recorder.open(path, "frusta"), FRUSTA_OK) << frusta::last_error_message();
    record(recorder, 0, "abc");
    record(recorder, 1000, "de");
    record(recorder, 2000, big);
    EXPECT_FALSE(recorder.failed());
  }
  std::string protocol;
  ASSERT_EQ(read_recording_protocol(path, &protocol), FRUSTA_OK);
  EXPECT_EQ(protocol, "frusta");
  for (bool loop : {false, true}) {
    ReplayStream replay(path, false, loop);
    std::string loaded;
    ASSERT_EQ(replay.load(&loaded), FRUSTA_OK) << frusta::last_error_message();
    EXPECT_EQ(loaded, "frusta");
    ASSERT_EQ(replay.open(), FRUSTA_OK);
    bool ended = false;
    const std::vector<std::string> reads = read_now(replay, &ended);
    EXPECT_TRUE(ended) << "as fast as read, nothing waits";
    ASSERT_EQ(reads.size(), 4u);
    EXPECT_EQ(reads[0], "abc");
    EXPECT_EQ(reads[1], "de");
    EXPECT_EQ(reads[2] + reads[3], big);
    EXPECT_EQ(replay.open(), loop ? FRUSTA_OK : FRUSTA_ERROR_WRONG_STATE) << "at its end it starts over, or not";
  }
  std::remove(path.c_str());
}

TEST(recording, InRealTimeARecordIsReadWhenDueAsFastAsReadAtOnce) {
  const std::string path = temp_path("recording");
  {
    Recorder recorder;
    ASSERT_EQ(recorder.open(path, "opengloves"), FRUSTA_OK);
    record(recorder, 0, "now\n");
    record(recorder, int64_t{3600} * 1000000000, "in an hour\n");
  }
  for (bool real_time : {true, false}) {
    ReplayStream replay(path, real_time, false);
    ASSERT_EQ(replay.open(), FRUSTA_OK);
    bool ended = false;
    const std::vector<std::string> reads = read_now(replay, &ended);
    // (the hour is the margin: only a test paused that long could see otherwise)
    if (real_time) {
      EXPECT_EQ(reads, std::vector<std::string>{"now\n"}) << "the second is not due";
      EXPECT_FALSE(ended);
    } else {
      EXPECT_EQ(reads, (std::vector<std::string>{"now\n", "in an hour\n"}));
      EXPECT_TRUE(ended);
    }
  }
  std::remove(path.c_str());
}

TEST(recording, ARecordCutOffAtTheEndIsPlayedAsFarAsItGoes) {
  const std::string path = temp_path("recording");
  {
    Recorder recorder;
    ASSERT_EQ(recorder.open(path, "opengloves"), FRUSTA_OK);
    record(recorder, 0, "A1\n");
    record(recorder, 10, "A2\nA3\n");
  }
  const int64_t whole = file_size(path);
  ASSERT_EQ(truncate(path.c_str(), whole - 2), 0);  // the recorder was killed mid-record
  {
    ReplayStream replay(path, false, false);
    ASSERT_EQ(replay.open(), FRUSTA_OK) << frusta::last_error_message();
    bool ended = false;
    EXPECT_EQ(read_now(replay, &ended), (std::vector<std::string>{"A1\n", "A2\nA"}));
  }
  ASSERT_EQ(truncate(path.c_str(), whole - 6 - 5), 0);  // ... in a record's head
  ReplayStream replay(path, false, false);
  ASSERT_EQ(replay.open(), FRUSTA_OK) << frusta::last_error_message();
  bool ended = false;
  EXPECT_EQ(read_now(replay, &ended), std::vector<std::string>{"A1\n"});
  std::remove(path.c_str());
}

TEST(recording, TheRecorderStopsAtItsLimitAndWhatItWroteReplays) {
  const std::string path = temp_path("recording");
  const std::string line(100, 'r');
  const int64_t header = static_cast<int64_t>(std::string("frusta-recording 1 opengloves\n").size());
  const int64_t limit = header + 2 * (12 + 100) + 50;  // two records and a half
  {
    Recorder recorder;
    ASSERT_EQ(recorder.open(path, "opengloves", limit), FRUSTA_OK);
    for (int i = 0; i < 3; ++i) record(recorder, i, line);
    EXPECT_TRUE(recorder.failed()) << "the third did not fit";
    record(recorder, 3, "A1\n");
    EXPECT_TRUE(recorder.failed()) << "and nothing after it is written either";
  }
  EXPECT_EQ(file_size(path), header + 2 * (12 + 100));
  ReplayStream replay(path, false, false);
  ASSERT_EQ(replay.open(), FRUSTA_OK) << frusta::last_error_message();
  bool ended = false;
  EXPECT_EQ(read_now(replay, &ended), (std::vector<std::string>{line, line}));
  std::remove(path.c_str());
}

TEST(recording, WhatIsNotARecordingIsRefusedByNameNeitherBlockingNorReadingWithoutEnd) {
  const scenes::HostileRecordings files(kMaxRecordingBytes);
  for (const scenes::HostilePath& hostile : files.replay) {
    // as the C ABI opens it: the URI, then the glove it names
    const scenes::ChildOutcome outcome = scenes::run_in_child([&](std::string* message) {
      DeviceAddress address;
      frusta_result r = parse_device_uri("replay:" + hostile.path, &address);
      Glove glove;
      if (r == FRUSTA_OK) r = make_glove(address, default_glove_calibration(), &glove);
      *message = last_error_message();
      return static_cast<int>(r);
    });
    if (!outcome.returned) {
      ADD_FAILURE() << hostile.path << ": " << outcome.message;
      continue;
    }
    EXPECT_EQ(outcome.result, hostile.code) << hostile.path << ": " << outcome.message;
    EXPECT_NE(outcome.message.find(hostile.path), std::string::npos) << outcome.message;
    EXPECT_NE(outcome.message.find(hostile.says), std::string::npos) << outcome.message;
  }
  // what the header names is read without reading the rest
  std::string protocol;
  EXPECT_EQ(read_recording_protocol(files.good, &protocol), FRUSTA_OK) << frusta::last_error_message();
  EXPECT_EQ(protocol, "opengloves");
}

TEST(recording, TheRecorderWritesOnlyToARegularFile) {
  const scenes::HostileRecordings files(kMaxRecordingBytes);
  for (const scenes::HostilePath& hostile : files.record_to) {
    const scenes::ChildOutcome outcome = scenes::run_in_child([&](std::string* message) {
      Recorder recorder;
      const frusta_result r = recorder.open(hostile.path, "opengloves");
      *message = last_error_message();
      return static_cast<int>(r);
    });
    if (!outcome.returned) {
      ADD_FAILURE() << hostile.path << ": " << outcome.message;
      continue;
    }
    EXPECT_EQ(outcome.result, hostile.code) << hostile.path << ": " << outcome.message;
    EXPECT_NE(outcome.message.find(hostile.path), std::string::npos) << outcome.message;
    EXPECT_NE(outcome.message.find(hostile.says), std::string::npos) << outcome.message;
  }
  // a regular file is recorded over
  const std::string path = temp_path("recorded-over");
  {
    std::ofstream(path) << std::string(1000, 'o');
    Recorder recorder;
    ASSERT_EQ(recorder.open(path, "frusta"), FRUSTA_OK) << frusta::last_error_message();
  }
  EXPECT_EQ(file_size(path), static_cast<int64_t>(std::string("frusta-recording 1 frusta\n").size()));
  std::remove(path.c_str());
}

}  // namespace
}  // namespace frusta
