// SPDX-License-Identifier: MIT
#include "tracking/joint_recording.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#ifndef _WIN32
#include <sys/stat.h>
#endif

#include "core/error.h"
#include "hand/anthropometry.h"
#include "scenes/random_hands.h"
#include "tracking/hand_fit.h"

namespace frusta {
namespace {

constexpr int32_t kXr = FRUSTA_JOINT_LAYOUT_XR;
constexpr int32_t kKeypoints = FRUSTA_JOINT_LAYOUT_KEYPOINTS;

// A few frames of a random hand moving, as a tracker would report them.
JointRecording random_recording(int32_t layout, int32_t side, int frames, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const HandModel model = make_hand_model(scenes::random_hand_def(side, rng));
  JointRecording r;
  r.layout = layout;
  r.side = side;
  for (int i = 0; i < frames; ++i) {
    const HandState s = scenes::random_hand_state(model, rng);
    const auto joints = scenes::tracked_joints(model, s, layout);
    r.times.push_back(i / 90.0);
    r.joints.insert(r.joints.end(), joints.begin(), joints.begin() + joint_count(layout));
  }
  return r;
}

std::string encoded(const JointRecording& r) {
  std::string text;
  EXPECT_EQ(encode_joint_recording(r, &text), FRUSTA_OK) << last_error_message();
  return text;
}

frusta_result decode(const std::string& text, JointRecording* out) {
  return decode_joint_recording(text.data(), text.size(), "test.csv", out);
}

// The round trip: what the writer writes reads back within its 6 decimals and writes
// back to the same text; a fitter given the read joints finds the same hand.
TEST(JointRecording, WritesWhatItReadsInBothLayoutsAndSides) {
  for (int32_t layout : {kXr, kKeypoints})
    for (int32_t side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
      const JointRecording original = random_recording(layout, side, 20, 17 + layout * 2 + side);
      const std::string text = encoded(original);
      JointRecording read;
      ASSERT_EQ(decode(text, &read), FRUSTA_OK) << last_error_message();
      EXPECT_EQ(read.layout, layout);
      EXPECT_EQ(read.side, side);
      ASSERT_EQ(read.frame_count(), 20);
      ASSERT_EQ(read.joints.size(), original.joints.size());
      for (size_t i = 0; i < read.times.size(); ++i)
        EXPECT_NEAR(read.times[i], original.times[i], 0.5e-6);
      for (size_t j = 0; j < read.joints.size(); ++j) {
        const TrackedJoint& a = original.joints[j];
        const TrackedJoint& b = read.joints[j];
        EXPECT_EQ(a.flags, b.flags);
        EXPECT_LE(glm::length(a.position - b.position), 1e-6);
        EXPECT_NEAR(a.radius, b.radius, 0.5e-6);
        if (a.flags & FRUSTA_JOINT_ORIENTATION_VALID) {
          for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.rotation[k], b.rotation[k], 0.5e-6);
        }
      }
      EXPECT_EQ(encoded(read), text) << "the text read writes back differently";
    }
}

// The first lines of a recording, as the writer writes them.
TEST(JointRecording, HeaderNamesLayoutSideUnitsAndColumns) {
  const std::string header = encode_joint_recording_header(kXr, FRUSTA_HAND_LEFT);
  EXPECT_EQ(header.rfind("frusta-tracked-joints,1\nlayout,openxr26\nside,left\nunits,metres,seconds\n"
                         "time,palm.px,palm.py,palm.pz,palm.qx,palm.qy,palm.qz,palm.qw,palm.radius,"
                         "palm.flags,wrist.px,",
                         0),
            0u);
  EXPECT_NE(header.find(",little_tip.flags\n"), std::string::npos);
  EXPECT_NE(encode_joint_recording_header(kKeypoints, FRUSTA_HAND_RIGHT)
                .find("layout,keypoints21\nside,right\n"),
            std::string::npos);
  EXPECT_STREQ(joint_name(kXr, 10), "index_tip");
  EXPECT_STREQ(joint_name(kKeypoints, 17), "little_mcp");
}

// Comments, blank lines and Windows line ends are read; fields a flag does not declare
// valid are written as zeros.
TEST(JointRecording, ReadsCommentsAndCrLfAndWritesInvalidFieldsAsZeros) {
  JointRecording r = random_recording(kKeypoints, FRUSTA_HAND_RIGHT, 2, 5);
  r.joints[3].flags = 0;
  r.joints[3].position = vec3(123.0, 4.0, 5.0);
  std::string text = encoded(r);
  const std::string zeros = ",0.000000,0.000000,0.000000,0.000000,0.000000,0.000000,1.000000,0.000000,0,";
  EXPECT_NE(text.find(zeros), std::string::npos);
  std::string crlf = "# a comment first\n\n";
  for (char c : text) crlf += c == '\n' ? std::string("\r\n# between\r\n") : std::string(1, c);
  JointRecording read;
  ASSERT_EQ(decode(crlf, &read), FRUSTA_OK) << last_error_message();
  EXPECT_EQ(read.frame_count(), 2);
  EXPECT_EQ(read.joints[3].flags, 0);
  EXPECT_EQ(read.joints[3].position, vec3(0.0));
}

struct Hostile {
  const char* what;
  std::string text;
  frusta_result code;
  const char* message;  // a part of the error that names the line and field
};

// One case per kind of defect: each refused with its code, the message naming the line
// and the field, and the output untouched.
TEST(JointRecording, RefusesEachKindOfDefectNamingLineAndField) {
  const JointRecording r = random_recording(kXr, FRUSTA_HAND_RIGHT, 3, 9);
  const std::string good = encoded(r);
  const std::string header = encode_joint_recording_header(kXr, FRUSTA_HAND_RIGHT);
  const size_t first = header.size();                    // the first frame's offset
  const size_t second = good.find('\n', first) + 1;      // the second's
  const std::string frame1 = good.substr(first, second - first);
  // the first frame with field k (0: time) replaced
  const auto with_field = [&](int k, const std::string& value) {
    std::string line = frame1;
    size_t begin = 0;
    for (int i = 0; i < k; ++i) begin = line.find(',', begin) + 1;
    size_t end = line.find_first_of(",\n", begin);
    return header + line.replace(begin, end - begin, value);
  };
  const int wrist_qw = 1 + 1 * kJointRecordingFields + 6;
  const int index_tip_flags = 1 + 10 * kJointRecordingFields + 8;
  const int thumb_tip_radius = 1 + 5 * kJointRecordingFields + 7;
  const std::vector<Hostile> cases = {
      {"empty", "", FRUSTA_ERROR_CORRUPT_FILE, "test.csv: ends before its first line"},
      {"only comments", "# nothing\n\n", FRUSTA_ERROR_CORRUPT_FILE, "ends before its first line"},
      {"another file", "time,x,y\n1,2,3\n", FRUSTA_ERROR_FILE_FORMAT, "test.csv:1: 'time,x,y' is not"},
      {"a later version", "frusta-tracked-joints,2\n", FRUSTA_ERROR_FILE_FORMAT, ":1:"},
      {"header cut short", "frusta-tracked-joints,1\nlayout,openxr26\n", FRUSTA_ERROR_CORRUPT_FILE,
       "ends before its side line"},
      {"unknown layout", "frusta-tracked-joints,1\nlayout,mano\n", FRUSTA_ERROR_CORRUPT_FILE,
       ":2: 'layout,mano'"},
      {"unknown side", "frusta-tracked-joints,1\nlayout,openxr26\nside,both\n",
       FRUSTA_ERROR_CORRUPT_FILE, ":3: 'side,both'"},
      {"other units", "frusta-tracked-joints,1\nlayout,openxr26\nside,left\nunits,millimetres,seconds\n",
       FRUSTA_ERROR_CORRUPT_FILE, ":4: 'units,millimetres,seconds'"},
      {"a column renamed", [&] {
         std::string t = good;
         t.replace(t.find("wrist.qw"), 8, "wrist.qq");
         return t;
       }(), FRUSTA_ERROR_CORRUPT_FILE, ":5: column 17 is 'wrist.qq', must be wrist.qw"},
      {"a column short", header.substr(0, header.size() - 18) + "\n", FRUSTA_ERROR_CORRUPT_FILE,
       "column 235 is 'missing'"},
      {"a column more", header.substr(0, header.size() - 1) + ",extra\n", FRUSTA_ERROR_CORRUPT_FILE,
       "more than the 235 columns"},
      {"no frames", header, FRUSTA_ERROR_CORRUPT_FILE, "test.csv: no frames"},
      {"a frame short", header + frame1.substr(0, frame1.rfind(',')) + "\n",
       FRUSTA_ERROR_CORRUPT_FILE, ":6: 234 fields, must be 235"},
      {"a frame cut off at the end", good.substr(0, second + 100), FRUSTA_ERROR_CORRUPT_FILE, ":7:"},
      {"a frame long", header + frame1.substr(0, frame1.size() - 1) + ",1\n",
       FRUSTA_ERROR_CORRUPT_FILE, ":6: more than 235 fields"},
      {"nan", with_field(wrist_qw, "nan"), FRUSTA_ERROR_CORRUPT_FILE, ":6: wrist.qw is 'nan'"},
      {"infinity", with_field(3, "inf"), FRUSTA_ERROR_CORRUPT_FILE, "palm.pz is 'inf'"},
      {"overflow", with_field(3, "1e400"), FRUSTA_ERROR_CORRUPT_FILE, "palm.pz is '1e400'"},
      {"hex", with_field(2, "0x1p3"), FRUSTA_ERROR_CORRUPT_FILE, "palm.py is '0x1p3'"},
      {"a plus sign", with_field(2, "+1"), FRUSTA_ERROR_CORRUPT_FILE, "palm.py is '+1'"},
      {"empty field", with_field(1, ""), FRUSTA_ERROR_CORRUPT_FILE, "palm.px is ''"},
      {"a comma for a point", with_field(1, "0;5"), FRUSTA_ERROR_CORRUPT_FILE, "palm.px is '0;5'"},
      {"trailing junk", with_field(1, "0.5x"), FRUSTA_ERROR_CORRUPT_FILE, "palm.px is '0.5x'"},
      {"a long number", with_field(1, "0." + std::string(40, '1')), FRUSTA_ERROR_CORRUPT_FILE,
       "palm.px is '0.1111"},
      {"beyond a million metres", with_field(1, "1000000.5"), FRUSTA_ERROR_CORRUPT_FILE,
       "palm.px is '1000000.5', not a plain decimal number within +-1e+06"},
      {"flags too big", with_field(index_tip_flags, "16"), FRUSTA_ERROR_CORRUPT_FILE,
       "index_tip.flags is '16', must be an integer 0..15"},
      {"flags negative", with_field(index_tip_flags, "-1"), FRUSTA_ERROR_CORRUPT_FILE,
       "index_tip.flags is '-1'"},
      {"flags fractional", with_field(index_tip_flags, "1.5"), FRUSTA_ERROR_CORRUPT_FILE,
       "index_tip.flags is '1.5'"},
      {"a rotation of norm 0", [&] {
         // the wrist's x, y, z, w all zero
         std::string line = frame1;
         size_t begin = 0;
         for (int i = 0; i < 1 + kJointRecordingFields + 3; ++i) begin = line.find(',', begin) + 1;
         size_t end = begin;
         for (int i = 0; i < 4; ++i) end = line.find(',', end) + 1;
         return header + line.replace(begin, end - begin, "0,0,0,0,");
       }(), FRUSTA_ERROR_CORRUPT_FILE, ":6: wrist: joints[1].rotation has norm 0"},
      {"a rotation of norm 0.5 that 6 decimals take below it", [&] {
         std::string line = frame1;
         size_t begin = 0;
         for (int i = 0; i < 1 + kJointRecordingFields + 3; ++i) begin = line.find(',', begin) + 1;
         size_t end = begin;
         for (int i = 0; i < 4; ++i) end = line.find(',', end) + 1;
         return header + line.replace(begin, end - begin, "0.3535534,0.3535534,0,0,");
       }(), FRUSTA_ERROR_CORRUPT_FILE, ":6: wrist: joints[1].rotation has norm 0.4999"},
      {"a negative radius", with_field(thumb_tip_radius, "-0.01"), FRUSTA_ERROR_CORRUPT_FILE,
       ":6: thumb_tip: joints[5].radius"},
      {"a negative time", with_field(0, "-1"), FRUSTA_ERROR_CORRUPT_FILE, ":6: time '-1'"},
      {"time over a million seconds", with_field(0, "1e7"), FRUSTA_ERROR_CORRUPT_FILE, "time '1e7'"},
      {"time standing still", header + frame1 + frame1, FRUSTA_ERROR_CORRUPT_FILE,
       ":7: time 0.000000 s is not a microsecond after"},
      {"time going back", good.substr(0, second) + frame1, FRUSTA_ERROR_CORRUPT_FILE,
       ":7: time 0.000000 s"},
      {"times within a microsecond", [&] {
         std::string t = with_field(0, "1.0000001");
         std::string line = t.substr(first);
         line.replace(0, line.find(','), "1.0000004");
         return t + line;
       }(), FRUSTA_ERROR_CORRUPT_FILE, ":7: time 1.0000004 s"},
      {"a NUL byte", [&] {
         std::string t = good;
         t[second + 3] = '\0';
         return t;
       }(), FRUSTA_ERROR_CORRUPT_FILE, ":7: a NUL byte"},
      {"a line too long", header + std::string(kMaxJointRecordingLine + 1, '1') + "\n",
       FRUSTA_ERROR_CORRUPT_FILE, ":6: the line is 8193 bytes long"},
  };
  for (const Hostile& c : cases) {
    JointRecording out;
    out.side = 7;  // a marker: a refused read leaves it
    const frusta_result code = decode(c.text, &out);
    EXPECT_EQ(code, c.code) << c.what << ": " << last_error_message();
    EXPECT_NE(std::string(last_error_message()).find(c.message), std::string::npos)
        << c.what << ": the error is\n  " << last_error_message() << "\nnot naming\n  " << c.message;
    EXPECT_EQ(out.side, 7) << c.what;
    EXPECT_EQ(out.frame_count(), 0) << c.what;
  }
  JointRecording out;
  EXPECT_EQ(decode(good, &out), FRUSTA_OK) << last_error_message();
}

// A recording of more frames than any may hold is refused at the first frame too many.
TEST(JointRecording, RefusesMoreFramesThanTheLimit) {
  // the shortest frames there are: every field 0 (no joint valid), 25 MB in all
  const std::string header = encode_joint_recording_header(kKeypoints, FRUSTA_HAND_RIGHT);
  std::string rest;
  for (int k = 0; k < FRUSTA_KEYPOINT_COUNT * kJointRecordingFields; ++k) rest += ",0";
  rest += '\n';
  std::string text = header;
  text.reserve(header.size() + (kMaxJointRecordingFrames + 1) * (rest.size() + 6));
  for (int i = 0; i <= kMaxJointRecordingFrames; ++i) text += std::to_string(i) + rest;
  JointRecording out;
  EXPECT_EQ(decode(text, &out), FRUSTA_ERROR_CORRUPT_FILE);
  EXPECT_NE(std::string(last_error_message()).find("more than 65536 frames"), std::string::npos)
      << last_error_message();
}

class JointRecordingFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("frusta_joint_recording_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

// The recorder writes frame by frame what the reader reads, and refuses what would not
// read back: times that do not move on by a microsecond, joints the fit would refuse.
TEST_F(JointRecordingFiles, RecorderWritesWhatTheLoaderReads) {
  const JointRecording r = random_recording(kXr, FRUSTA_HAND_LEFT, 5, 21);
  JointRecorder recorder;
  ASSERT_EQ(recorder.open(path("a.csv"), kXr, FRUSTA_HAND_LEFT, "two lines\nof comment"), FRUSTA_OK)
      << last_error_message();
  for (int32_t i = 0; i < r.frame_count(); ++i)
    ASSERT_EQ(recorder.add(r.times[static_cast<size_t>(i)], r.frame(i)), FRUSTA_OK) << last_error_message();
  EXPECT_EQ(recorder.add(r.times.back(), r.frame(0)), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(last_error_message()).find("not a microsecond after"), std::string::npos);
  std::vector<TrackedJoint> bad(r.frame(0), r.frame(0) + FRUSTA_XR_JOINT_COUNT);
  bad[4].position.y = NAN;
  EXPECT_EQ(recorder.add(10.0, bad.data()), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(std::string(last_error_message()).find("joints[4].position"), std::string::npos)
      << last_error_message();
  EXPECT_EQ(recorder.add(NAN, r.frame(0)), FRUSTA_ERROR_NOT_FINITE);
  // a rotation of norm just over 0.5, which 6 decimals would take below it: written, it
  // would not read back
  std::vector<TrackedJoint> edge(r.frame(0), r.frame(0) + FRUSTA_XR_JOINT_COUNT);
  edge[2].rotation = glm::dquat(0.0, 0.3535534, 0.3535534, 0.0);
  ASSERT_GE(glm::length(edge[2].rotation), 0.5);
  EXPECT_EQ(recorder.add(10.0, edge.data()), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(last_error_message()).find("joints (to 6 decimals)[2].rotation has norm"),
            std::string::npos)
      << last_error_message();
  ASSERT_EQ(recorder.close(), FRUSTA_OK);

  JointRecording read;
  ASSERT_EQ(load_joint_recording(path("a.csv"), &read), FRUSTA_OK) << last_error_message();
  EXPECT_EQ(read.frame_count(), 5);
  EXPECT_EQ(read.side, FRUSTA_HAND_LEFT);
  std::string text;
  ASSERT_EQ(encode_joint_recording(read, &text), FRUSTA_OK);
  std::ifstream in(path("a.csv"), std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(file.find("\n# two lines\n# of comment\n"), std::string::npos);
  std::string without_comments;
  for (size_t at = 0; at < file.size();) {
    const size_t end = file.find('\n', at) + 1;
    if (file[at] != '#') without_comments += file.substr(at, end - at);
    at = end;
  }
  EXPECT_EQ(without_comments, text);
}

// Files that are not recordings are refused before they are read: missing, a directory,
// too large (a sparse file: nothing is read), a FIFO and a device (they could block or
// never end).
TEST_F(JointRecordingFiles, LoaderRefusesWhatIsNotARegularFileOfBoundedSize) {
  JointRecording out;
  EXPECT_EQ(load_joint_recording(path("missing.csv"), &out), FRUSTA_ERROR_IO);
  EXPECT_NE(std::string(last_error_message()).find("missing.csv"), std::string::npos);
  EXPECT_EQ(load_joint_recording(dir_.string(), &out), FRUSTA_ERROR_IO);
  EXPECT_NE(std::string(last_error_message()).find("not a regular file"), std::string::npos);
  {
    std::ofstream big(path("big.csv"), std::ios::binary);
  }
  std::filesystem::resize_file(path("big.csv"), static_cast<uintmax_t>(kMaxJointRecordingBytes) + 1);
  EXPECT_EQ(load_joint_recording(path("big.csv"), &out), FRUSTA_ERROR_CORRUPT_FILE);
  EXPECT_NE(std::string(last_error_message()).find("more than a recording may hold"), std::string::npos)
      << last_error_message();
  JointRecorder recorder;
  EXPECT_EQ(recorder.open(dir_.string(), kXr, FRUSTA_HAND_RIGHT), FRUSTA_ERROR_IO);
  EXPECT_EQ(recorder.open(path("x.csv"), 2, FRUSTA_HAND_RIGHT), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(recorder.open(path("x.csv"), kXr, 2), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(recorder.add(0.0, nullptr), FRUSTA_ERROR_WRONG_STATE);
#ifndef _WIN32
  ASSERT_EQ(mkfifo(path("fifo").c_str(), 0600), 0);
  EXPECT_EQ(load_joint_recording(path("fifo"), &out), FRUSTA_ERROR_IO);
  EXPECT_EQ(recorder.open(path("fifo"), kXr, FRUSTA_HAND_RIGHT), FRUSTA_ERROR_IO);
  EXPECT_EQ(load_joint_recording("/dev/zero", &out), FRUSTA_ERROR_IO);
#endif
  EXPECT_EQ(out.frame_count(), 0);
}

// The demo's bundled recording (samples/data, made by frusta-make-recording) reads, and
// a fitter of the hand it was made from fits it to its writer's resolution.
TEST(JointRecording, BundledDemoRecordingReadsAndFits) {
  JointRecording r;
  ASSERT_EQ(load_joint_recording(FRUSTA_TRACKED_RECORDING, &r), FRUSTA_OK) << last_error_message();
  EXPECT_EQ(r.layout, kXr);
  EXPECT_EQ(r.side, FRUSTA_HAND_RIGHT);
  ASSERT_GT(r.frame_count(), 400);
  const double rate = (r.frame_count() - 1) / (r.times.back() - r.times.front());
  EXPECT_NEAR(rate, 90.0, 1e-6);
  HandFitter fitter(make_hand_model(default_hand_def()), HandFitOptions{});
  double worst = 0.0;
  for (int32_t i = 0; i < r.frame_count(); ++i) {
    HandFit fit;
    fitter.fit(r.frame(i), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
    EXPECT_EQ(fit.palm_flags, 0) << "frame " << i;
    for (double residual : fit.finger_residual) worst = std::max(worst, residual);
  }
  std::printf("bundled recording: %d frames, worst finger residual %.3g m\n", r.frame_count(), worst);
  EXPECT_LT(worst, 5e-6);
}

}  // namespace
}  // namespace frusta
