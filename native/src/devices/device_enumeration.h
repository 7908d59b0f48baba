// SPDX-License-Identifier: MIT
// What could be a glove on this machine now: serial ports (serial_ports.h),
// vendor-defined HID devices, and every USB device (for its ids). Slow (it walks /dev
// or the registry, hidapi and the USB device list: usb_watch.h): host only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace frusta {

struct DeviceInfo {
  int32_t kind = 0;  // frusta_device_kind
  int32_t vendor_id = -1, product_id = -1;
  std::string uri;   // serial:PATH, hid:VID:PID[:SERIAL], or usb:BUS:ADDRESS
};

void enumerate_devices(std::vector<DeviceInfo>* out);

}  // namespace frusta
