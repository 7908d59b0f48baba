// SPDX-License-Identifier: MIT
// Where a glove is and what it speaks, from the URI a host opens it by (frusta.h,
// "devices"): opengloves:PATH?baud=N, serial:PATH?baud=N, hid:VID:PID[:SERIAL],
// replay:FILE?speed=1|max&loop=0|1, each with an optional &record=FILE.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/base.h"

namespace frusta {

enum class DeviceKind { kOpenGloves, kSerial, kHid, kReplay };

struct DeviceAddress {
  DeviceKind kind = DeviceKind::kSerial;
  std::string path;          // serial port or recording file
  int32_t baud = 115200;
  uint16_t vendor_id = 0, product_id = 0;
  std::string serial_number;  // hid: empty matches any
  bool real_time = true;      // replay: speed=1 (else max)
  bool loop = false;          // replay: start over at the end
  std::string record_path;    // empty: not recorded
};

// The thread's error names the part of the URI at fault and what was expected.
frusta_result parse_device_uri(std::string_view uri, DeviceAddress* out);

}  // namespace frusta
