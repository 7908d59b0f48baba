// SPDX-License-Identifier: MIT
// What could be a glove on this machine now: serial ports (USB serial, Bluetooth
// RFCOMM, and the stable /dev/serial/by-id names), vendor-defined HID devices, and
// every USB device (for its ids). Slow (it walks /dev, hidapi and libusb): host only.
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
