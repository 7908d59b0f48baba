// SPDX-License-Identifier: MIT
#include "tracking/joint_recording.h"

#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/file_read.h"
#include "core/validate.h"

namespace frusta {

namespace {

constexpr std::string_view kMagic = "frusta-tracked-joints,1";
constexpr std::string_view kUnits = "units,metres,seconds";
constexpr double kMaxTime = 1e6;  // seconds: 11 days
constexpr int kMaxFlags = FRUSTA_JOINT_ORIENTATION_VALID | FRUSTA_JOINT_POSITION_VALID |
                          FRUSTA_JOINT_ORIENTATION_TRACKED | FRUSTA_JOINT_POSITION_TRACKED;
constexpr const char* kFieldNames[kJointRecordingFields] = {"px", "py", "pz", "qx", "qy",
                                                            "qz", "qw", "radius", "flags"};

constexpr std::array<const char*, FRUSTA_XR_JOINT_COUNT> kXrNames = {
    "palm",               "wrist",             "thumb_metacarpal",  "thumb_proximal",
    "thumb_distal",       "thumb_tip",         "index_metacarpal",  "index_proximal",
    "index_intermediate", "index_distal",      "index_tip",         "middle_metacarpal",
    "middle_proximal",    "middle_intermediate", "middle_distal",   "middle_tip",
    "ring_metacarpal",    "ring_proximal",     "ring_intermediate", "ring_distal",
    "ring_tip",           "little_metacarpal", "little_proximal",   "little_intermediate",
    "little_distal",      "little_tip"};
constexpr std::array<const char*, FRUSTA_KEYPOINT_COUNT> kKeypointNames = {
    "wrist",      "thumb_cmc",  "thumb_mcp",  "thumb_ip",   "thumb_tip",  "index_mcp",
    "index_pip",  "index_dip",  "index_tip",  "middle_mcp", "middle_pip", "middle_dip",
    "middle_tip", "ring_mcp",   "ring_pip",   "ring_dip",   "ring_tip",   "little_mcp",
    "little_pip", "little_dip", "little_tip"};

const char* layout_name(int32_t layout) {
  return layout == FRUSTA_JOINT_LAYOUT_XR ? "openxr26" : "keypoints21";
}

std::string column_header(int32_t layout) {
  std::string line = "time";
  for (int j = 0; j < joint_count(layout); ++j)
    for (const char* field : kFieldNames) {
      line += ',';
      line += joint_name(layout, j);
      line += '.';
      line += field;
    }
  return line;
}

// A value to the file's resolution: the double nearest k / 10^6 for the integer k
// nearest value * 10^6, never a negative zero. The reader keeps what it reads so and the
// writer writes so, each checking the joints after rounding (else a quaternion of norm
// just over 0.5 could be written, rounded below it, and refused on reading). For
// |value| <= kMaxCoordinate, value * 10^6 is within 2^53.
double quantised(double value) { return std::round(value * 1e6) / 1e6 + 0.0; }

// a quantised value's 6 decimals (the double nearest k / 10^6 prints as exactly k / 10^6)
void append_fixed(double value, std::string* out) {
  char buffer[48];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, quantised(value),
                                               std::chars_format::fixed, 6);
  assert(r.ec == std::errc());
  out->append(buffer, static_cast<size_t>(r.ptr - buffer));
}

// a joint with every field quantised, and those its flags do not declare valid zero
// (rotation: identity)
TrackedJoint quantised(const TrackedJoint& joint) {
  TrackedJoint q;
  q.flags = joint.flags;
  if (joint.flags & FRUSTA_JOINT_POSITION_VALID) {
    q.position = vec3(quantised(joint.position.x), quantised(joint.position.y),
                      quantised(joint.position.z));
    q.radius = quantised(joint.radius);
  }
  if (joint.flags & FRUSTA_JOINT_ORIENTATION_VALID)
    q.rotation = glm::dquat(quantised(joint.rotation.w), quantised(joint.rotation.x),
                            quantised(joint.rotation.y), quantised(joint.rotation.z));
  return q;
}

// Reads a text one line at a time, bounded, naming the line in errors.
class Lines {
 public:
  Lines(const char* text, size_t size, const char* name) : text_(text), size_(size), name_(name) {}

  // The next line that is not a comment, in *line; false at the end or on an error
  // (then *result is set).
  bool next(std::string_view* line, frusta_result* result) {
    while (position_ < size_) {
      const char* start = text_ + position_;
      const void* newline = std::memchr(start, '\n', size_ - position_);
      size_t length = newline ? static_cast<size_t>(static_cast<const char*>(newline) - start)
                              : size_ - position_;
      position_ += length + (newline ? 1 : 0);
      ++number_;
      if (length > 0 && start[length - 1] == '\r') --length;
      if (length > kMaxJointRecordingLine) {
        *result = error(FRUSTA_ERROR_CORRUPT_FILE, "the line is %zu bytes long, more than %zu",
                        length, kMaxJointRecordingLine);
        return false;
      }
      if (std::memchr(start, '\0', length)) {
        *result = error(FRUSTA_ERROR_CORRUPT_FILE, "%s", "a NUL byte: not a text file");
        return false;
      }
      if (length == 0 || start[0] == '#') continue;
      *line = std::string_view(start, length);
      return true;
    }
    *result = FRUSTA_OK;
    return false;
  }

  // fail() with "name:line: " before the message
  template <class... Args>
  frusta_result error(frusta_result code, const char* format, Args... args) const {
    char message[512];
    std::snprintf(message, sizeof message, format, args...);
    return fail(code, "%s:%d: %s", name_, number_, message);
  }

  const char* name() const { return name_; }
  int number() const { return number_; }

 private:
  const char* text_;
  size_t size_, position_ = 0;
  const char* name_;
  int number_ = 0;
};

// a token shown in an error: at most 40 characters of it
std::string shown(std::string_view token) {
  std::string s(token.substr(0, 40));
  if (token.size() > 40) s += "...";
  return s;
}

// A plain decimal number within +-kMaxCoordinate: digits, a leading minus, a point, an
// exponent. from_chars, unlike strtod, ignores the locale and knows no nan, inf or hex
// beyond what the character check already refused.
bool parse_number(std::string_view token, double* out) {
  if (token.empty() || token.size() > kMaxJointRecordingToken) return false;
  if (token.find_first_not_of("0123456789-+.eE") != std::string_view::npos) return false;
  if (token[0] == '+') return false;
  double value = 0.0;
  const std::from_chars_result r =
      std::from_chars(token.data(), token.data() + token.size(), value, std::chars_format::general);
  if (r.ec != std::errc() || r.ptr != token.data() + token.size()) return false;
  if (!std::isfinite(value) || std::fabs(value) > kMaxCoordinate) return false;
  *out = value;
  return true;
}

// The fields of a line split at commas, without allocating; false if there are more
// than `capacity`.
int split(std::string_view line, std::string_view* fields, int capacity) {
  int n = 0;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    if (n == capacity) return capacity + 1;
    fields[n++] = line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                      : comma - start);
    if (comma == std::string_view::npos) return n;
    start = comma + 1;
  }
}

}  // namespace

const char* joint_name(int32_t layout, int index) {
  assert(is_joint_layout(layout) && index >= 0 && index < joint_count(layout));
  return layout == FRUSTA_JOINT_LAYOUT_XR ? kXrNames[static_cast<size_t>(index)]
                                          : kKeypointNames[static_cast<size_t>(index)];
}

frusta_result decode_joint_recording(const char* text, size_t size, const char* name,
                                     JointRecording* out) {
  if (!text && size > 0) return fail(FRUSTA_ERROR_NULL_POINTER, "%s: no text", name);
  if (size > static_cast<size_t>(kMaxJointRecordingBytes))
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: %zu bytes, more than %lld", name, size,
                static_cast<long long>(kMaxJointRecordingBytes));
  Lines lines(text, size, name);
  std::string_view line;
  frusta_result result = FRUSTA_OK;
  // the header, in order
  const auto header_line = [&](const char* what) -> bool {
    if (lines.next(&line, &result)) return true;
    if (result == FRUSTA_OK)
      result = fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: ends before its %s line", name, what);
    return false;
  };
  if (!header_line("first")) return result;
  if (line != kMagic)
    return lines.error(FRUSTA_ERROR_FILE_FORMAT, "'%s' is not '%.*s': not a tracked-joint recording",
                       shown(line).c_str(), static_cast<int>(kMagic.size()), kMagic.data());
  JointRecording recording;
  if (!header_line("layout")) return result;
  if (line == "layout,openxr26") {
    recording.layout = FRUSTA_JOINT_LAYOUT_XR;
  } else if (line == "layout,keypoints21") {
    recording.layout = FRUSTA_JOINT_LAYOUT_KEYPOINTS;
  } else {
    return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                       "'%s': the layout line must be layout,openxr26 or layout,keypoints21",
                       shown(line).c_str());
  }
  if (!header_line("side")) return result;
  if (line == "side,right") {
    recording.side = FRUSTA_HAND_RIGHT;
  } else if (line == "side,left") {
    recording.side = FRUSTA_HAND_LEFT;
  } else {
    return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                       "'%s': the side line must be side,right or side,left", shown(line).c_str());
  }
  if (!header_line("units")) return result;
  if (line != kUnits)
    return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "'%s': the units line must be %.*s",
                       shown(line).c_str(), static_cast<int>(kUnits.size()), kUnits.data());
  if (!header_line("column")) return result;
  const std::string columns = column_header(recording.layout);
  if (line != columns) {
    // name the first column that differs
    std::array<std::string_view, 1 + kMaxTrackedJoints * kJointRecordingFields> got, want;
    const int n = split(line, got.data(), static_cast<int>(got.size()));
    const int m = split(columns, want.data(), static_cast<int>(want.size()));
    int k = 0;
    while (k < n && k < m && got[static_cast<size_t>(k)] == want[static_cast<size_t>(k)]) ++k;
    if (k < m)
      return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "column %d is '%s', must be %s (layout %s)",
                         k + 1, k < n ? shown(got[static_cast<size_t>(k)]).c_str() : "missing",
                         std::string(want[static_cast<size_t>(k)]).c_str(),
                         layout_name(recording.layout));
    return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "more than the %d columns of layout %s", m,
                       layout_name(recording.layout));
  }

  // the frames
  const int count = joint_count(recording.layout);
  const int fields_per_frame = 1 + count * kJointRecordingFields;
  std::array<std::string_view, 1 + kMaxTrackedJoints * kJointRecordingFields> fields;
  std::array<TrackedJoint, kMaxTrackedJoints> joints;
  int64_t last_us = -1;
  while (lines.next(&line, &result)) {
    if (recording.frame_count() == kMaxJointRecordingFrames)
      return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "more than %d frames", kMaxJointRecordingFrames);
    const int n = split(line, fields.data(), fields_per_frame);
    if (n != fields_per_frame)
      return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "%s%d fields, must be %d (time, then %d per joint)",
                         n > fields_per_frame ? "more than " : "", n > fields_per_frame ? fields_per_frame : n,
                         fields_per_frame, kJointRecordingFields);
    double time = 0.0;
    if (!parse_number(fields[0], &time) || time < 0.0)
      return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                         "time '%s' is not a plain decimal number of seconds in 0..%g",
                         shown(fields[0]).c_str(), kMaxTime);
    // read to the microsecond, as written: a replay divides by the time between frames
    const int64_t time_us = std::llround(time * 1e6);
    if (time_us <= last_us)
      return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                         "time %s s is not a microsecond after the previous frame's",
                         shown(fields[0]).c_str());
    last_us = time_us;
    for (int j = 0; j < count; ++j) {
      double v[kJointRecordingFields - 1];
      for (int k = 0; k < kJointRecordingFields - 1; ++k) {
        const std::string_view token = fields[static_cast<size_t>(1 + j * kJointRecordingFields + k)];
        if (!parse_number(token, &v[k]))
          return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                             "%s.%s is '%s', not a plain decimal number within +-%g",
                             joint_name(recording.layout, j), kFieldNames[k], shown(token).c_str(),
                             kMaxCoordinate);
      }
      const std::string_view flags = fields[static_cast<size_t>(1 + j * kJointRecordingFields + 8)];
      int flag_value = -1;
      if (flags.size() <= 2 && !flags.empty() &&
          flags.find_first_not_of("0123456789") == std::string_view::npos)
        std::from_chars(flags.data(), flags.data() + flags.size(), flag_value);
      if (flag_value < 0 || flag_value > kMaxFlags)
        return lines.error(FRUSTA_ERROR_CORRUPT_FILE,
                           "%s.flags is '%s', must be an integer 0..%d (frusta_joint_flag bits)",
                           joint_name(recording.layout, j), shown(flags).c_str(), kMaxFlags);
      TrackedJoint& joint = joints[static_cast<size_t>(j)];
      // to the file's resolution, as the writer would write it; fields the flags do not
      // declare valid are dropped
      TrackedJoint read;
      read.position = vec3(v[0], v[1], v[2]);
      read.rotation = glm::dquat(v[6], v[3], v[4], v[5]);  // w first
      read.radius = v[7];
      read.flags = flag_value;
      joint = quantised(read);
      if (const frusta_result r = check_tracked_joint(joint, "joints", j)) {
        // the check's message, less the name of its code
        const std::string why = last_error_detail(r);
        return lines.error(FRUSTA_ERROR_CORRUPT_FILE, "%s: %s", joint_name(recording.layout, j),
                           why.c_str());
      }
    }
    recording.times.push_back(static_cast<double>(time_us) / 1e6);
    recording.joints.insert(recording.joints.end(), joints.begin(), joints.begin() + count);
  }
  if (result != FRUSTA_OK) return result;
  if (recording.times.empty())
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: no frames", name);
  *out = std::move(recording);
  return FRUSTA_OK;
}

frusta_result load_joint_recording(const std::string& path, JointRecording* out) {
  std::vector<uint8_t> text;
  if (frusta_result r = read_file(path, static_cast<size_t>(kMaxJointRecordingBytes),
                                  "a recording may hold", &text))
    return r;
  return decode_joint_recording(reinterpret_cast<const char*>(text.data()), text.size(),
                                path.c_str(), out);
}

std::string encode_joint_recording_header(int32_t layout, int32_t side) {
  assert(is_joint_layout(layout));
  std::string out(kMagic);
  out += "\nlayout,";
  out += layout_name(layout);
  out += side == FRUSTA_HAND_LEFT ? "\nside,left\n" : "\nside,right\n";
  out += kUnits;
  out += '\n';
  out += column_header(layout);
  out += '\n';
  return out;
}

frusta_result encode_joint_frame(int32_t layout, double time, const TrackedJoint* joints,
                                 std::string* out) {
  if (frusta_result r = check_joint_layout(layout, "layout")) return r;
  if (frusta_result r = check_range(time, 0.0, kMaxTime, false, "time")) return r;
  if (frusta_result r = check_tracked_joints(joints, joint_count(layout), layout, "joints")) return r;
  // what is written is checked too: rounding may take a valid value out of its range
  std::array<TrackedJoint, kMaxTrackedJoints> written;
  for (int j = 0; j < joint_count(layout); ++j) written[static_cast<size_t>(j)] = quantised(joints[j]);
  if (frusta_result r = check_tracked_joints(written.data(), joint_count(layout), layout,
                                             "joints (to 6 decimals)"))
    return r;
  append_fixed(time, out);
  for (int j = 0; j < joint_count(layout); ++j) {
    const TrackedJoint& joint = written[static_cast<size_t>(j)];
    const vec3& p = joint.position;
    const glm::dquat& q = joint.rotation;
    for (double v : {p.x, p.y, p.z, q.x, q.y, q.z, q.w, joint.radius}) {
      *out += ',';
      append_fixed(v, out);
    }
    *out += ',';
    *out += std::to_string(joint.flags);
  }
  *out += '\n';
  return FRUSTA_OK;
}

frusta_result encode_joint_recording(const JointRecording& recording, std::string* out) {
  if (frusta_result r = check_joint_layout(recording.layout, "recording.layout")) return r;
  const size_t count = static_cast<size_t>(joint_count(recording.layout));
  if (recording.joints.size() != recording.times.size() * count)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "recording has %zu joints for %zu frames of %zu",
                recording.joints.size(), recording.times.size(), count);
  std::string text = encode_joint_recording_header(recording.layout, recording.side);
  for (int32_t i = 0; i < recording.frame_count(); ++i)
    if (frusta_result r = encode_joint_frame(recording.layout, recording.times[static_cast<size_t>(i)],
                                             recording.frame(i), &text))
      return r;
  *out = std::move(text);
  return FRUSTA_OK;
}

JointRecorder::~JointRecorder() {
  if (file_) std::fclose(file_);
}

frusta_result JointRecorder::open(const std::string& path, int32_t layout, int32_t side,
                                  const std::string& comment) {
  if (file_) return fail(FRUSTA_ERROR_WRONG_STATE, "%s: the recorder is open already", path.c_str());
  if (frusta_result r = check_joint_layout(layout, "layout")) return r;
  if (side != FRUSTA_HAND_RIGHT && side != FRUSTA_HAND_LEFT)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "side is %d, must be FRUSTA_HAND_RIGHT or _LEFT", side);
  // never a FIFO or a device: opening one could block, writing one never end
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return fail(FRUSTA_ERROR_IO, "%s: not a regular file (a directory, a device or a pipe)",
                path.c_str());
  std::FILE* file = std::fopen(path.c_str(), "wb");  // binary: '\n' on every system
  if (!file) return fail(FRUSTA_ERROR_IO, "%s: cannot create it", path.c_str());
  std::string header = encode_joint_recording_header(layout, side);
  size_t from = 0;
  while (!comment.empty() && from <= comment.size()) {
    const size_t end = comment.find('\n', from);
    header += "# ";
    header += comment.substr(from, end == std::string::npos ? std::string::npos : end - from);
    header += '\n';
    if (end == std::string::npos) break;
    from = end + 1;
  }
  if (std::fwrite(header.data(), 1, header.size(), file) != header.size()) {
    std::fclose(file);
    return fail(FRUSTA_ERROR_IO, "%s: cannot write its header", path.c_str());
  }
  file_ = file;
  path_ = path;
  layout_ = layout;
  frames_ = 0;
  written_ = static_cast<int64_t>(header.size());
  return FRUSTA_OK;
}

frusta_result JointRecorder::add(double time, const TrackedJoint* joints) {
  if (!file_) return fail(FRUSTA_ERROR_WRONG_STATE, "the joint recorder is not open");
  if (frusta_result r = check_range(time, 0.0, kMaxTime, false, "time")) return r;
  if (frames_ > 0 && std::llround(time * 1e6) <= std::llround(last_time_ * 1e6))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "time %.9g s is not a microsecond after the last frame's (%.9g s)", time, last_time_);
  if (frames_ == kMaxJointRecordingFrames)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: holds %d frames, the most a recording may",
                path_.c_str(), kMaxJointRecordingFrames);
  line_.clear();
  if (frusta_result r = encode_joint_frame(layout_, time, joints, &line_)) return r;
  if (written_ + static_cast<int64_t>(line_.size()) > kMaxJointRecordingBytes)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: would grow past %lld bytes", path_.c_str(),
                static_cast<long long>(kMaxJointRecordingBytes));
  if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size())
    return fail(FRUSTA_ERROR_IO, "%s: cannot write frame %lld", path_.c_str(),
                static_cast<long long>(frames_));
  written_ += static_cast<int64_t>(line_.size());
  last_time_ = time;
  ++frames_;
  return FRUSTA_OK;
}

frusta_result JointRecorder::close() {
  if (!file_) return FRUSTA_OK;
  const bool failed = std::ferror(file_) != 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (failed || !closed) return fail(FRUSTA_ERROR_IO, "%s: writing failed", path_.c_str());
  return FRUSTA_OK;
}

}  // namespace frusta
