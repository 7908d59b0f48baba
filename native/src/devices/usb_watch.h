// SPDX-License-Identifier: MIT
// The USB devices present (their ids, so a host can offer the gloves it knows) and
// notice of arrivals and departures, so a host can refresh its list without polling
// the bus. From the platform's own API, so the runtime ships without libusb (LGPL):
// Linux reads sysfs and listens to the kernel's uevents on a netlink socket (what
// libusb does there); Windows asks SetupAPI and has no hot-plug (neither had libusb).
// Host only: a watch is made, used and dropped by one thread, and makes no thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/base.h"

namespace frusta {

struct UsbDeviceInfo {
  int32_t vendor_id = 0, product_id = 0;
  int32_t bus = 0, address = 0;  // Linux: bus and device number; Windows: hub and port
};

class UsbWatch {
 public:
  // sysfs_devices: where Linux lists USB devices (tests pass a folder of their own)
  explicit UsbWatch(std::string sysfs_devices = "/sys/bus/usb/devices");
  ~UsbWatch();
  UsbWatch(const UsbWatch&) = delete;
  UsbWatch& operator=(const UsbWatch&) = delete;

  // The devices present, by bus then address (none where the system has no USB bus).
  // FRUSTA_ERROR_IO when the platform refuses the list (the message says why).
  frusta_result enumerate(std::vector<UsbDeviceInfo>* out);
  // Starts counting arrivals and departures. FRUSTA_ERROR_IO where there is no
  // hot-plug here (then a host polls enumerate).
  frusta_result watch_hotplug();
  // Waits up to timeout_us for hot-plug events; returns the arrivals and departures
  // seen since the last call.
  int32_t poll_changes(int64_t timeout_us);

 private:
  std::string sysfs_devices_;
  int netlink_ = -1;  // Linux: the uevent socket while watching
};

// Linux: how many of the kernel uevents in a netlink datagram ("ACTION@DEVPATH\0KEY=VALUE\0...")
// are a whole USB device arriving or leaving (its interfaces' events are not counted).
int32_t count_usb_uevents(const char* data, size_t size);

}  // namespace frusta
