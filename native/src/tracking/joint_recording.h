// SPDX-License-Identifier: MIT
// Tracked joints on file: what a tracker reported, frame by frame, to replay through a
// hand fitter (the demo, tests, bug reports), as glove recordings are replayed through
// a glove's decoder. Host-side I/O: nothing on the 1 kHz path reads or writes it.
//
// A text CSV (one record a line, '\n' or "\r\n"; lines starting with '#' and empty lines
// are comments), in this order:
//   frusta-tracked-joints,1
//   layout,openxr26          openxr26: FRUSTA_JOINT_LAYOUT_XR; keypoints21: _KEYPOINTS
//   side,right               right | left: the hand the joints are of
//   units,metres,seconds     positions and radii in metres, time in seconds
//   time,palm.px,palm.py,palm.pz,palm.qx,palm.qy,palm.qz,palm.qw,palm.radius,palm.flags,
//       wrist.px,...         the column names: time, then 9 per joint of the layout
//   0.000000,...             frames: time, then per joint position (x, y, z), rotation
//                            (quaternion x, y, z, w; OpenXR's joint axes), radius (0:
//                            unknown) and flags (frusta_joint_flag bits, 0..15)
// The joints are in one frame of the writer's choosing (a tracker's origin); the fit
// takes that frame's pose. Joint names (kJointNames): XR's XrHandJointEXT order
// (palm, wrist, thumb_metacarpal, thumb_proximal, thumb_distal, thumb_tip,
// index_metacarpal, index_proximal, index_intermediate, index_distal, index_tip, ...),
// keypoints MediaPipe's (wrist, thumb_cmc, thumb_mcp, thumb_ip, thumb_tip, index_mcp,
// index_pip, index_dip, index_tip, ...); fingers thumb, index, middle, ring, little.
//
// Reading refuses, naming the line and column: a file that is not a regular file, over
// kMaxJointRecordingBytes, a line over kMaxJointRecordingLine bytes or with a NUL byte,
// a header out of order or unknown, a frame with the wrong number of fields, a field
// that is not a plain decimal number (digits, sign, point, exponent: no nan, inf or hex)
// of at most kMaxJointRecordingToken characters, a number beyond +-kMaxCoordinate, times
// that do not increase (by at least a microsecond), flags that are not an integer 0..15,
// a joint that check_tracked_joint refuses, more than kMaxJointRecordingFrames frames or
// none. Values are kept to 6 decimals (1 um, 1 us, 1e-6 of a quaternion: far below a
// tracker's noise) by both sides: the writer writes them so, checks the rounded joints,
// and what it writes reads back and writes again to the same text. Fields a joint's
// flags do not declare valid are read as, and written as, zeros (rotation: identity).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/base.h"
#include "tracking/hand_joints.h"

namespace frusta {

// 64 MiB: 6 minutes of XR joints at 90 Hz as the writer writes them (2 kB a frame)
constexpr int64_t kMaxJointRecordingBytes = int64_t{64} << 20;
constexpr int32_t kMaxJointRecordingFrames = 65536;
// a frame of 26 joints of 9 fields of 32 characters fits
constexpr size_t kMaxJointRecordingLine = 8192;
constexpr size_t kMaxJointRecordingToken = 32;
// the writer's resolution: times at least this far apart stay apart on file
constexpr double kJointRecordingResolution = 1e-6;

// Fields per joint on a frame line: position 3, rotation 4, radius, flags.
constexpr int kJointRecordingFields = 9;

// The name of joint `index` of a layout on file (e.g. "index_tip").
const char* joint_name(int32_t layout, int index);

struct JointRecording {
  int32_t layout = FRUSTA_JOINT_LAYOUT_XR;  // frusta_joint_layout
  int32_t side = FRUSTA_HAND_RIGHT;         // frusta_hand_side
  std::vector<double> times;                // seconds, increasing
  std::vector<TrackedJoint> joints;         // frame-major, joint_count(layout) a frame

  int32_t frame_count() const { return static_cast<int32_t>(times.size()); }
  const TrackedJoint* frame(int32_t i) const {
    return joints.data() + static_cast<size_t>(i) * static_cast<size_t>(joint_count(layout));
  }
};

// Parse a whole recording from `size` bytes of text; `name` prefixes errors (a path).
// On failure *out is left as it was.
frusta_result decode_joint_recording(const char* text, size_t size, const char* name,
                                     JointRecording* out);
// Read and parse a file (a regular file of at most kMaxJointRecordingBytes).
frusta_result load_joint_recording(const std::string& path, JointRecording* out);

// The header lines of a layout and side, and one frame line: what the writer writes.
// The frame's joints are checked first (check_tracked_joints, the time finite, 0..1e6 s),
// and again once rounded to 6 decimals.
std::string encode_joint_recording_header(int32_t layout, int32_t side);
frusta_result encode_joint_frame(int32_t layout, double time, const TrackedJoint* joints,
                                 std::string* out);
// A whole recording, as text.
frusta_result encode_joint_recording(const JointRecording& recording, std::string* out);

// Writes a recording frame by frame (a live tracker's, or a generator's): each frame is
// checked as encode_joint_frame does, and its time must exceed the last by
// kJointRecordingResolution, so that whatever it writes reads back.
class JointRecorder {
 public:
  JointRecorder() = default;
  JointRecorder(const JointRecorder&) = delete;
  JointRecorder& operator=(const JointRecorder&) = delete;
  ~JointRecorder();
  // Creates `path` (or empties it) and writes the header; comment: lines written
  // after it as '#' comments (may be empty; '\n' separates lines).
  frusta_result open(const std::string& path, int32_t layout, int32_t side,
                     const std::string& comment = {});
  frusta_result add(double time, const TrackedJoint* joints);
  // Flushes and closes; an error if any write failed.
  frusta_result close();

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  int32_t layout_ = FRUSTA_JOINT_LAYOUT_XR;
  double last_time_ = 0.0;
  int64_t frames_ = 0, written_ = 0;
  std::string line_;  // reused
};

}  // namespace frusta
