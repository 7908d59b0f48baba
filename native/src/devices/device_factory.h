// SPDX-License-Identifier: MIT
// The wire and the protocol a device URI names: opengloves: is the alpha encoding over
// serial, serial: and hid: our binary profile, replay: whatever its recording holds.
#pragma once

#include <memory>
#include <string>

#include "devices/byte_stream.h"
#include "devices/device_uri.h"
#include "devices/glove_calibration.h"
#include "devices/glove_protocol.h"

namespace frusta {

struct Glove {
  std::unique_ptr<ByteStream> stream;
  std::unique_ptr<GloveProtocol> protocol;
  std::string protocol_name;  // "opengloves" or "frusta", as recordings name them
};

// Nothing is opened yet; a replay's recording is read for its protocol.
frusta_result make_glove(const DeviceAddress& address, const GloveCalibration& calibration,
                         Glove* out);

}  // namespace frusta
