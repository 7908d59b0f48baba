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
constexpr int kIndex = FRUSTA_FINGER_INDEX;
constexpr int kLittle = FRUSTA_FINGER_LITTLE;
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
  const double m = median(samples, count);
  for (int i = 0; i < count; ++i) samples[i] = std::fabs(samples[i] - m);
  const double sigma = kMadToSigma * median(samples, count);
  // m = d + sigma^2 / d to first order; beyond a noise of half the length, keep half
  return m > 0.0 ? std::max(m - sigma * sigma / m, 0.5 * m) : m;
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
  wrist_to_middle_.reserve(frames);
  index_to_little_.reserve(frames);
}

void HandCalibration::add_frame(const TrackedJoint* joints) {
  auto chain = [&](int f, int k) -> const TrackedJoint& { return joints[chain_joint(layout_, f, k)]; };
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) bones_[f][s].add(chain(f, s), chain(f, s + 1));
  wrist_to_middle_.add(joints[wrist_joint(layout_)], chain(kMiddle, 0));
  index_to_little_.add(chain(kIndex, 0), chain(kLittle, 0));
  ++frames_;
}

frusta_result HandCalibration::size(HandDef* def) {
  const char* missing = wrist_to_middle_.empty() ? "the wrist and the middle finger's MCP joint"
                        : index_to_little_.empty() ? "the index and the little finger's MCP joints"
                        : bones_[kMiddle][0].empty() ? "the middle finger's MCP and PIP joints"
                        : bones_[kMiddle][1].empty() ? "the middle finger's PIP and DIP joints"
                        : bones_[kMiddle][2].empty() ? "the middle finger's DIP joint and tip"
                                                     : nullptr;
  if (missing)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "frames: %s are never tracked together in the %d frames (both need "
                "FRUSTA_JOINT_POSITION_VALID and FRUSTA_JOINT_POSITION_TRACKED): the hand's "
                "size cannot be measured", missing, frames_);

  double bone_lengths[FRUSTA_FINGER_COUNT][FRUSTA_SEGMENTS_PER_FINGER] = {};
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      if (!bones_[f][s].empty()) bone_lengths[f][s] = bones_[f][s].length();

  // the anthropometry's geometry is linear in length and breadth: its parts per metre
  HandDef per_length, per_breadth;
  fill_hand_geometry(per_length, 1.0, 0.0);
  fill_hand_geometry(per_breadth, 0.0, 1.0);
  const double middle_across = per_breadth.base_position[kMiddle][1];
  const double spread_along = per_length.base_position[kIndex][0] - per_length.base_position[kLittle][0];
  const double spread_across = per_breadth.base_position[kIndex][1] - per_breadth.base_position[kLittle][1];

  // hand length: the middle MCP joint's distance along the hand plus the finger's bones
  // (the last to the fingertip's end); breadth: whatever puts the index and little MCP
  // joints as far apart as measured. Each needs the other a little: iterate.
  const double wrist_middle = wrist_to_middle_.length();
  const double index_little = index_to_little_.length();
  const double finger = bone_lengths[kMiddle][0] + bone_lengths[kMiddle][1] + bone_lengths[kMiddle][2];
  double breadth = index_little / std::fabs(spread_across), length = 0.0;
  for (int iteration = 0; iteration < 16; ++iteration) {
    const double across = middle_across * breadth;
    length = std::sqrt(std::max(wrist_middle * wrist_middle - across * across, 0.0)) + finger;
    const double along = spread_along * length;
    breadth = std::sqrt(std::max(index_little * index_little - along * along, 0.0)) / std::fabs(spread_across);
  }
  if (!(length >= kMinHandSize && length <= kMaxHandSize && breadth >= kMinHandSize &&
        breadth <= kMaxHandSize))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "frames: the joints give hand_length %g m and hand_breadth %g m, beyond %g..%g m",
                length, breadth, kMinHandSize, kMaxHandSize);

  HandDef sized = *def;
  fill_hand_geometry(sized, length, breadth);
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
