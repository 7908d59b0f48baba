// SPDX-License-Identifier: MIT
#include "tracking/hand_calibration.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "hand/anthropometry.h"

namespace frusta {

namespace {

constexpr int32_t kCounted = FRUSTA_JOINT_POSITION_VALID | FRUSTA_JOINT_POSITION_TRACKED;
constexpr int kMiddle = FRUSTA_FINGER_MIDDLE;
// the normal distribution's standard deviation over its median absolute deviation
constexpr double kMadToSigma = 1.4826;

bool counted(const TrackedJoint& j) { return (j.flags & kCounted) == kCounted; }

double median(double* values, int count) {
  const int half = count / 2;
  std::nth_element(values, values + half, values + count);
  const double upper = values[half];
  if (count % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values, values + half));
}

}  // namespace

double bone_length(double* samples, int count) {
  // the mean of the middle half: robust to a quarter of bad frames either way (and to
  // one of three), and nearer the mean's efficiency on Gaussian noise than the median
  std::sort(samples, samples + count);
  const int low = count >= 3 ? std::max(count / 4, 1) : 0, high = count - low;
  double sum = 0.0;
  for (int i = low; i < high; ++i) sum += samples[i];
  const double centre = sum / (high - low);
  const double m = median(samples, count);
  for (int i = 0; i < count; ++i) samples[i] = std::fabs(samples[i] - m);
  const double sigma = kMadToSigma * median(samples, count);
  // centre = d + sigma^2 / d to first order; beyond a noise of half the length, keep half
  return centre > 0.0 ? std::max(centre - sigma * sigma / centre, 0.5 * centre) : centre;
}

void HandCalibration::Distances::add(const TrackedJoint& a, const TrackedJoint& b) {
  if (counted(a) && counted(b)) samples_.push_back(glm::distance(a.position, b.position));
}

double HandCalibration::Distances::length() {
  return bone_length(samples_.data(), static_cast<int>(samples_.size()));
}

HandCalibration::HandCalibration(int32_t layout, int frames) : layout_(layout) {
  for (auto& finger : bones_)
    for (Distances& bone : finger) bone.reserve(frames);
  for (Distances& pair : palm_) pair.reserve(frames);
}

int HandCalibration::palm_joint(int point) const {
  return point == 0 ? wrist_joint(layout_) : chain_joint(layout_, point - 1, 0);
}

void HandCalibration::add_frame(const TrackedJoint* joints) {
  auto chain = [&](int f, int k) -> const TrackedJoint& { return joints[chain_joint(layout_, f, k)]; };
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) bones_[f][s].add(chain(f, s), chain(f, s + 1));
  int pair = 0;
  for (int i = 0; i < kPalmPoints; ++i)
    for (int j = i + 1; j < kPalmPoints; ++j) palm_[pair++].add(joints[palm_joint(i)], joints[palm_joint(j)]);
  ++frames_;
}

frusta_result HandCalibration::size(HandDef* def) {
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
    if (bones_[kMiddle][s].empty())
      return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                  "frames: the middle finger's %s are never tracked together in the %d frames "
                  "(both need FRUSTA_JOINT_POSITION_VALID and FRUSTA_JOINT_POSITION_TRACKED): the "
                  "hand's length cannot be measured",
                  s == 0 ? "MCP and PIP joints" : s == 1 ? "PIP and DIP joints" : "DIP joint and tip",
                  frames_);
  double bone_lengths[FRUSTA_FINGER_COUNT][FRUSTA_SEGMENTS_PER_FINGER] = {};
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      if (!bones_[f][s].empty()) bone_lengths[f][s] = bones_[f][s].length();

  // The anthropometry puts the palm's joints at (a L, b B, 0) for hand length L and
  // breadth B (its geometry is linear in both): a squared distance between two is
  // da^2 L^2 + db^2 B^2, linear in L^2 and B^2. Least squares over every pair measured,
  // each weighed by the inverse of its noise's variance (noise on d^2 grows with d).
  HandDef per_length, per_breadth;
  fill_hand_geometry(per_length, 1.0, 0.0);
  fill_hand_geometry(per_breadth, 0.0, 1.0);
  auto along = [&](int point) { return point == 0 ? 0.0 : per_length.base_position[point - 1][0]; };
  auto across = [&](int point) { return point == 0 ? 0.0 : per_breadth.base_position[point - 1][1]; };
  double m[2][2] = {}, rhs[2] = {};
  int pair = 0;
  for (int i = 0; i < kPalmPoints; ++i)
    for (int j = i + 1; j < kPalmPoints; ++j, ++pair) {
      if (palm_[pair].empty()) continue;
      const double d = palm_[pair].length();
      if (!(d > 0.0)) continue;
      const double a = (along(i) - along(j)) * (along(i) - along(j));
      const double b = (across(i) - across(j)) * (across(i) - across(j));
      const double w = 1.0 / (d * d);
      m[0][0] += w * a * a;
      m[0][1] += w * a * b;
      m[1][1] += w * b * b;
      rhs[0] += w * a * d * d;
      rhs[1] += w * b * d * d;
    }
  const double det = m[0][0] * m[1][1] - m[0][1] * m[0][1];
  if (!(det > 1e-9 * m[0][0] * m[1][1]))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "frames: the palm's joints (the wrist, the thumb's CMC and the MCP joints) are "
                "not tracked in pairs that give both the palm's length and its breadth in the %d "
                "frames (both joints of a pair need FRUSTA_JOINT_POSITION_VALID and "
                "FRUSTA_JOINT_POSITION_TRACKED)", frames_);
  const double palm_scale = std::sqrt(std::max((rhs[0] * m[1][1] - rhs[1] * m[0][1]) / det, 0.0));
  const double breadth = std::sqrt(std::max((rhs[1] * m[0][0] - rhs[0] * m[0][1]) / det, 0.0));
  // hand length: wrist crease to the straight middle fingertip, its MCP joint where the
  // palm's scale puts it plus the finger's bones (the last to the fingertip's end)
  const double length = along(1 + kMiddle) * palm_scale + bone_lengths[kMiddle][0] +
                        bone_lengths[kMiddle][1] + bone_lengths[kMiddle][2];
  if (!(length >= kMinHandSize && length <= kMaxHandSize && breadth >= kMinHandSize &&
        breadth <= kMaxHandSize))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "frames: the joints give hand_length %g m and hand_breadth %g m, beyond %g..%g m",
                length, breadth, kMinHandSize, kMaxHandSize);

  HandDef sized = *def;
  fill_hand_geometry(sized, length, breadth);
  // the palm as measured: its joints along the hand at the palm's own scale
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) sized.base_position[f][0] = along(1 + f) * palm_scale;
  sized.palm_length = sized.base_position[kMiddle][0];
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      if (bones_[f][s].empty()) continue;
      // the last bone runs to the fingertip's end, the segment to the tip ball's centre
      const double measured = bone_lengths[f][s] - (s == 2 ? sized.joint_radius[f][3] : 0.0);
      if (measured >= kMinHandPart) sized.segment_length[f][s] = measured;
    }
  if (frusta_result r = check_hand_def(sized)) {
    const std::string part = last_error_message();
    return fail(r, "frames: the joints give hand_length %g m and hand_breadth %g m, which make "
                "no valid hand: %s", length, breadth, part.c_str());
  }
  *def = sized;
  return FRUSTA_OK;
}

}  // namespace frusta
