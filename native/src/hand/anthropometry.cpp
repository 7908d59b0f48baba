// SPDX-License-Identifier: MIT
#include "hand/anthropometry.h"

namespace frusta {

namespace {

constexpr int kThumb = FRUSTA_FINGER_THUMB;

// Link lengths as fractions of hand length, thumb to little finger, after Buchholz,
// Armstrong & Goldstein, "Anthropometric data for describing the kinematics of the
// human hand", Ergonomics 35(3):261-273, 1992. Columns: metacarpal, proximal,
// middle, distal phalanx (joint centre to joint centre; the distal one to the tip).
// The thumb has no middle phalanx: its chain is metacarpal, proximal, distal.
constexpr double kLinkRatio[FRUSTA_FINGER_COUNT][4] = {
    {0.251, 0.196, 0.158, 0.0},    // thumb
    {0.374, 0.265, 0.143, 0.097},  // index
    {0.373, 0.277, 0.170, 0.108},  // middle
    {0.336, 0.259, 0.165, 0.107},  // ring
    {0.295, 0.206, 0.117, 0.093},  // little
};
// The middle finger's links sum to 0.928: the remaining 0.072 of hand length lies
// between the wrist crease and the carpometacarpal joints, so the default middle
// fingertip ends exactly at hand_length.
constexpr double kWristToCarpometacarpal = 1.0 - (0.373 + 0.277 + 0.170 + 0.108);

// Joint ball radii as fractions of hand breadth (first joint, second, third, tip):
// half the mean finger breadths at the joints of the U.S. Army hand survey (Greiner,
// "Hand anthropometry of U.S. Army personnel", NATICK TR-92/011, 1991) over its
// mean hand breadth, rounded; they decrease proximal to distal as the seed requires.
constexpr double kRadiusRatio[FRUSTA_FINGER_COUNT][4] = {
    {0.170, 0.145, 0.125, 0.110},  // thumb: CMC, MCP, IP, tip
    {0.135, 0.124, 0.106, 0.094},  // index: MCP, PIP, DIP, tip
    {0.140, 0.128, 0.108, 0.096},  // middle
    {0.130, 0.118, 0.100, 0.090},  // ring
    {0.115, 0.103, 0.090, 0.080},  // little
};

// Finger bases across the metacarpal heads (fraction of breadth, + towards the thumb)
// and their slight fan (radians about z); the thumb's carpometacarpal base sits
// near the wrist on the radial side, turned so that it flexes across the palm.
constexpr double kBaseAcross[FRUSTA_FINGER_COUNT] = {0.30, 0.3375, 0.1125, -0.1125, -0.3375};
constexpr double kBaseFan[FRUSTA_FINGER_COUNT] = {0.70, 0.06, 0.0, -0.06, -0.12};
constexpr double kThumbBaseAlong = 0.12;   // fraction of hand length from the wrist
constexpr double kThumbRoll = -1.0;        // radians about x: the thumb's pad faces the fingers
constexpr double kThumbPitch = 0.2;        // radians about y: the metacarpal points palmar
constexpr double kPalmThicknessRatio = 0.35;  // of breadth: ~3 cm at 8.5 cm

// Ranges of motion, radians: abduction, then flexion of the first, second, third
// joint. Fingers after the AAOS "Joint Motion: Method of Measuring and Recording"
// (1965) and Hume et al., "Functional range of motion of the joints of the hand",
// J Hand Surg 15A:240-243, 1990 (MCP -20..90 deg, PIP 0..110, DIP -5..80,
// abduction +-20); thumb CMC abduction -15..50, CMC flexion -20..50, MCP -10..60,
// IP -15..80 deg.
constexpr double kDefaultHandLength = 0.19;  // metres, about the adult 50th percentile
constexpr double kDefaultHandBreadth = 0.085;

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kFingerMin[4] = {-20 * kDeg, -20 * kDeg, 0.0, -5 * kDeg};
constexpr double kFingerMax[4] = {20 * kDeg, 90 * kDeg, 110 * kDeg, 80 * kDeg};
constexpr double kThumbMin[4] = {-15 * kDeg, -20 * kDeg, -10 * kDeg, -15 * kDeg};
constexpr double kThumbMax[4] = {50 * kDeg, 50 * kDeg, 60 * kDeg, 80 * kDeg};

}  // namespace

void fill_hand_geometry(HandDef& def, double hand_length, double hand_breadth) {
  def.hand_length = hand_length;
  def.hand_breadth = hand_breadth;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int j = 0; j < 4; ++j) def.joint_radius[f][j] = kRadiusRatio[f][j] * hand_breadth;
    // the thumb's three segments are its links 0-2; a finger's are links 1-3
    const int first_link = f == kThumb ? 0 : 1;
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      def.segment_length[f][s] = kLinkRatio[f][first_link + s] * hand_length;
    // the tip hemisphere covers the last part of the distal phalanx
    def.segment_length[f][2] -= def.joint_radius[f][3];

    const double along = f == kThumb ? kThumbBaseAlong
                                     : kWristToCarpometacarpal + kLinkRatio[f][0];
    def.base_position[f][0] = along * hand_length;
    def.base_position[f][1] = kBaseAcross[f] * hand_breadth;
    def.base_position[f][2] = 0.0;
    def.base_rotation[f][0] = f == kThumb ? kThumbRoll : 0.0;
    def.base_rotation[f][1] = f == kThumb ? kThumbPitch : 0.0;
    def.base_rotation[f][2] = kBaseFan[f];
  }
  def.palm_length = def.base_position[FRUSTA_FINGER_MIDDLE][0];
  def.palm_breadth = hand_breadth;
  def.palm_thickness = kPalmThicknessRatio * hand_breadth;
}

void fill_joint_limits(HandDef& def) {
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      def.joint_min[f][j] = f == kThumb ? kThumbMin[j] : kFingerMin[j];
      def.joint_max[f][j] = f == kThumb ? kThumbMax[j] : kFingerMax[j];
    }
  }
}

HandDef default_hand_def() {
  HandDef def;
  fill_hand_geometry(def, kDefaultHandLength, kDefaultHandBreadth);
  fill_joint_limits(def);
  return def;
}

}  // namespace frusta
