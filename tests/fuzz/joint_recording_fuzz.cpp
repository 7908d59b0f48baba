// SPDX-License-Identifier: MIT
// libFuzzer target: the tracked-joint recording reader must refuse or accept any bytes
// without a crash, a sanitizer report or an unbounded allocation. What it accepts must
// write out (the writer checks every joint again) and read back to the same recording:
// the written text is a fixed point of reading and writing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "tracking/joint_recording.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  frusta::JointRecording recording;
  if (frusta::decode_joint_recording(reinterpret_cast<const char*>(data), size, "fuzz",
                                     &recording) != FRUSTA_OK)
    return 0;
  std::string text, again;
  frusta::JointRecording read;
  if (frusta::encode_joint_recording(recording, &text) != FRUSTA_OK) std::abort();
  if (frusta::decode_joint_recording(text.data(), text.size(), "fuzz", &read) != FRUSTA_OK)
    std::abort();
  if (read.frame_count() != recording.frame_count() || read.layout != recording.layout ||
      read.side != recording.side)
    std::abort();
  if (frusta::encode_joint_recording(read, &again) != FRUSTA_OK || again != text) std::abort();
  return 0;
}
