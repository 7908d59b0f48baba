// SPDX-License-Identifier: MIT
// OpenGloves' "alpha encoding" (LucidVR opengloves-driver wiki, "Driver Input"; also
// Monado's drv_opengloves), spoken by LucidGloves firmware and its kin over USB or
// Bluetooth serial. ASCII lines ending in '\n', each a run of keys and decimal values:
//
//   glove -> host   A..E          curl of the thumb..little finger, 0..analog max (4095)
//                   (AB)..(EB)    splay of the thumb..little finger, centred at max / 2
//                   (AAA)..(EAD)  curl of one joint: finger letter, 'A', joint letter
//                                 A..D. Fingers' joints 0..3 are the metacarpal, the
//                                 knuckle, the middle and the end joint; the thumb's
//                                 0..2 its base, middle and end joint (no 3)
//                   F G P         joystick x, y, analog trigger (0..max)
//                   H..O          flags, sent only while set: joystick click, trigger,
//                                 A, B, grab, pinch, menu, calibrate
//                   (ZV)(ZG)(ZH)  firmware version, device type, hand: information
//   host -> glove   A<n>B<n>C<n>D<n>E<n>  one brake per finger, 0 (free) to 1000 (locked)
//
// This file is the codec both ways (the engine's side and a glove's); it knows nothing
// of angles or newtons: glove_calibration does that.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "devices/glove_calibration.h"

namespace frusta {

enum class AlphaLine {
  kSample,      // at least one finger's curl or splay
  kNoFingers,   // valid, but only buttons, joystick or information
  kCorrupt,     // a key or character the encoding does not have, a finger key without value
  kTruncated,   // begins inside a value: the line's start was lost (joined mid-stream)
  kOutOfRange,  // a finger value beyond analog_max, or too many digits for any ADC
};

// Decode one line (without its '\n'; a trailing '\r' is allowed). *out is written only
// for kSample. Per-joint curls override the finger's; a joint without a value of its
// own takes the finger's curl, else its nearest reported neighbour's.
AlphaLine decode_alpha_line(std::string_view line, double analog_max, RawGloveReading* out);

// The host's brake command line, '\n' included; returns its length (0 if capacity is
// too small; 40 bytes always suffice). Units are clamped to [0, 9999].
size_t encode_alpha_brakes(const std::array<int32_t, FRUSTA_FINGER_COUNT>& units, char* out,
                           size_t capacity);

// The glove's side: an input line for `reading` ('\n' included; 0 if capacity is too
// small; 256 bytes always suffice), with per-joint keys when per_joint, else one curl
// per finger (its first flexion joint's). Values are rounded to integers.
size_t encode_alpha_input(const RawGloveReading& reading, bool per_joint, char* out,
                          size_t capacity);

// The glove's side: a brake command line; false unless it holds all five brakes.
bool decode_alpha_brakes(std::string_view line, std::array<int32_t, FRUSTA_FINGER_COUNT>* units);

}  // namespace frusta
