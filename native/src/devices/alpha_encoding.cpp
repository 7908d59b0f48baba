// SPDX-License-Identifier: MIT
#include "devices/alpha_encoding.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frusta {

namespace {

constexpr int32_t kOpenGlovesJoints = 4;  // per finger on the wire (the thumb uses 3)
constexpr size_t kMaxDigits = 9;          // no ADC has more; beyond is noise

bool is_key_letter(char c) { return c >= 'A' && c <= 'Z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
int32_t finger_of(char c) { return c >= 'A' && c <= 'E' ? c - 'A' : -1; }

// The wire joint our flexion joint j of finger f reads: fingers skip the metacarpal.
int32_t wire_joint(int32_t finger, int32_t j) { return finger == FRUSTA_FINGER_THUMB ? j : j + 1; }

struct FingerValues {
  bool has_curl = false, has_splay = false;
  double curl = 0.0, splay = 0.0;
  std::array<bool, kOpenGlovesJoints> has_joint{};
  std::array<double, kOpenGlovesJoints> joint{};
};

// The value of wire joint `joint`, else the finger's curl, else the nearest joint's.
double joint_value(const FingerValues& v, int32_t joint) {
  if (v.has_joint[joint]) return v.joint[joint];
  if (v.has_curl) return v.curl;
  for (int32_t d = 1; d < kOpenGlovesJoints; ++d) {
    if (joint - d >= 0 && v.has_joint[joint - d]) return v.joint[joint - d];
    if (joint + d < kOpenGlovesJoints && v.has_joint[joint + d]) return v.joint[joint + d];
  }
  return 0.0;
}

}  // namespace

AlphaLine decode_alpha_line(std::string_view line, double analog_max, RawGloveReading* out) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (!line.empty() && is_digit(line.front())) return AlphaLine::kTruncated;
  std::array<FingerValues, FRUSTA_FINGER_COUNT> fingers{};
  bool any_finger = false;
  size_t i = 0;
  while (i < line.size()) {
    // a key: one letter, or two or three letters in brackets
    char key[3] = {0, 0, 0};
    size_t key_length = 0;
    if (is_key_letter(line[i])) {
      key[key_length++] = line[i++];
    } else if (line[i] == '(') {
      ++i;
      while (i < line.size() && is_key_letter(line[i]) && key_length < 3) key[key_length++] = line[i++];
      if (key_length < 2 || i >= line.size() || line[i] != ')') return AlphaLine::kCorrupt;
      ++i;
    } else {
      return AlphaLine::kCorrupt;
    }
    // its value: decimal digits, possibly none (a flag)
    size_t digits = 0;
    double value = 0.0;
    while (i < line.size() && is_digit(line[i])) {
      if (++digits > kMaxDigits) return AlphaLine::kOutOfRange;
      value = value * 10.0 + (line[i++] - '0');
    }
    const int32_t finger = finger_of(key[0]);
    const bool curl = key_length == 1 && finger >= 0;
    const bool splay = key_length == 2 && finger >= 0 && key[1] == 'B';
    const int32_t joint = key_length == 3 && finger >= 0 && key[1] == 'A' ? key[2] - 'A' : -1;
    const bool joint_key = joint >= 0 && joint < kOpenGlovesJoints;
    if (!curl && !splay && !joint_key) continue;  // buttons, joystick, information, newer keys
    if (digits == 0) return AlphaLine::kCorrupt;
    if (value > analog_max) return AlphaLine::kOutOfRange;
    FingerValues& v = fingers[static_cast<size_t>(finger)];
    if (curl) {
      v.has_curl = true;
      v.curl = value;
    } else if (splay) {
      v.has_splay = true;
      v.splay = value;
    } else {
      v.has_joint[static_cast<size_t>(joint)] = true;
      v.joint[static_cast<size_t>(joint)] = value;
    }
    any_finger = true;
  }
  if (!any_finger) return AlphaLine::kNoFingers;

  RawGloveReading r;
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerValues& v = fingers[static_cast<size_t>(f)];
    r.has_splay[f] = v.has_splay;
    r.splay[f] = v.splay;
    r.has_curl[f] = v.has_curl || std::any_of(v.has_joint.begin(), v.has_joint.end(),
                                              [](bool b) { return b; });
    for (int32_t j = 0; j < kFlexionJoints; ++j) r.curl[f][j] = joint_value(v, wire_joint(f, j));
  }
  *out = r;
  return AlphaLine::kSample;
}

size_t encode_alpha_brakes(const std::array<int32_t, FRUSTA_FINGER_COUNT>& units, char* out,
                           size_t capacity) {
  int32_t u[FRUSTA_FINGER_COUNT];
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) u[f] = std::clamp(units[f], 0, 9999);
  const int n = std::snprintf(out, capacity, "A%dB%dC%dD%dE%d\n", u[0], u[1], u[2], u[3], u[4]);
  return n > 0 && static_cast<size_t>(n) < capacity ? static_cast<size_t>(n) : 0;
}

size_t encode_alpha_input(const RawGloveReading& reading, bool per_joint, char* out,
                          size_t capacity) {
  size_t length = 0;
  const auto append = [&](const char* format, auto... args) {
    if (length >= capacity) return;
    const int n = std::snprintf(out + length, capacity - length, format, args...);
    length = n < 0 ? capacity : length + static_cast<size_t>(n);
  };
  const auto whole = [](double v) { return static_cast<long>(std::lround(std::max(v, 0.0))); };
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const char letter = static_cast<char>('A' + f);
    if (!reading.has_curl[f]) continue;
    append("%c%ld", letter, whole(reading.curl[f][0]));
    if (!per_joint) continue;
    for (int32_t j = 0; j < kFlexionJoints; ++j)
      append("(%cA%c)%ld", letter, static_cast<char>('A' + wire_joint(f, j)), whole(reading.curl[f][j]));
  }
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    if (reading.has_splay[f]) append("(%cB)%ld", static_cast<char>('A' + f), whole(reading.splay[f]));
  }
  append("\n");
  return length < capacity ? length : 0;
}

bool decode_alpha_brakes(std::string_view line, std::array<int32_t, FRUSTA_FINGER_COUNT>* units) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  std::array<int32_t, FRUSTA_FINGER_COUNT> u{};
  std::array<bool, FRUSTA_FINGER_COUNT> seen{};
  size_t i = 0;
  while (i < line.size()) {
    const int32_t finger = finger_of(line[i++]);
    if (finger < 0) return false;
    int32_t value = 0;
    size_t digits = 0;
    while (i < line.size() && is_digit(line[i]) && digits < 5) {
      value = value * 10 + (line[i++] - '0');
      ++digits;
    }
    if (digits == 0) return false;
    u[static_cast<size_t>(finger)] = value;
    seen[static_cast<size_t>(finger)] = true;
  }
  if (!std::all_of(seen.begin(), seen.end(), [](bool b) { return b; })) return false;
  *units = u;
  return true;
}

}  // namespace frusta
