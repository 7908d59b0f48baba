// SPDX-License-Identifier: MIT
#include "devices/device_factory.h"

#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "devices/frusta_protocol.h"
#include "devices/hid_stream.h"
#include "devices/opengloves_protocol.h"
#include "devices/recording.h"
#include "devices/serial_stream.h"

namespace frusta {

namespace {

constexpr char kOpenGloves[] = "opengloves";
constexpr char kFrusta[] = "frusta";

frusta_result make_protocol(const std::string& name, const GloveCalibration& calibration,
                            Glove* out) {
  if (name == kOpenGloves) {
    out->protocol = std::make_unique<OpenGlovesProtocol>(calibration);
  } else if (name == kFrusta) {
    out->protocol = std::make_unique<FrustaProtocol>();
  } else {
    return fail(FRUSTA_ERROR_FILE_FORMAT, "unknown glove protocol \"%s\" (expected %s or %s)",
                name.c_str(), kOpenGloves, kFrusta);
  }
  out->protocol_name = name;
  return FRUSTA_OK;
}

}  // namespace

frusta_result make_glove(const DeviceAddress& address, const GloveCalibration& calibration,
                         Glove* out) {
  Glove glove;
  switch (address.kind) {
    case DeviceKind::kOpenGloves:
      glove.stream = std::make_unique<SerialStream>(address.path, address.baud);
      if (frusta_result r = make_protocol(kOpenGloves, calibration, &glove)) return r;
      break;
    case DeviceKind::kSerial:
      glove.stream = std::make_unique<SerialStream>(address.path, address.baud);
      if (frusta_result r = make_protocol(kFrusta, calibration, &glove)) return r;
      break;
    case DeviceKind::kHid:
      glove.stream = std::make_unique<HidStream>(address.vendor_id, address.product_id,
                                                 address.serial_number);
      if (frusta_result r = make_protocol(kFrusta, calibration, &glove)) return r;
      break;
    case DeviceKind::kReplay: {
      std::error_code ignored;  // either missing: not the same file
      if (!address.record_path.empty() &&
          std::filesystem::equivalent(address.record_path, address.path, ignored))
        return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                    "record=%s is the recording being replayed: recording over it would destroy "
                    "it", address.record_path.c_str());
      // read and checked once, here: the file is not read again at open
      auto replay = std::make_unique<ReplayStream>(address.path, address.real_time, address.loop);
      std::string name;
      if (frusta_result r = replay->load(&name)) return r;
      if (make_protocol(name, calibration, &glove) != FRUSTA_OK)
        return fail(FRUSTA_ERROR_FILE_FORMAT, "recording %s: unknown glove protocol \"%s\" (expected %s or %s)",
                    address.path.c_str(), name.c_str(), kOpenGloves, kFrusta);
      glove.stream = std::move(replay);
      break;
    }
  }
  *out = std::move(glove);
  return FRUSTA_OK;
}

}  // namespace frusta
