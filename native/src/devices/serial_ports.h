// SPDX-License-Identifier: MIT
// The serial ports a glove could be on, as serial: URIs, for device enumeration:
// /dev/serial/by-id first (stable across replugs), then USB serial and RFCOMM nodes
// (serial_ports_posix.cpp); on Windows the COM ports the drivers registered
// (serial_ports_win32.cpp).
#pragma once

#include <vector>

#include "devices/device_enumeration.h"

namespace frusta {

// Appends one DeviceInfo per port, in a stable order.
void list_serial_ports(std::vector<DeviceInfo>* out);

}  // namespace frusta
