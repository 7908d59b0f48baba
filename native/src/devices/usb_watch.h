// SPDX-License-Identifier: MIT
// libusb for what it is best at: the USB devices present (their ids, so a host can
// offer the gloves it knows) and notice of arrivals and departures, so a host can
// refresh its list without polling the bus. Host only: a watch is made, used and
// dropped by one thread; it makes no thread of its own until hot-plug is asked for
// (libusb then watches the kernel's uevents on one).
#pragma once

#include <cstdint>
#include <vector>

#include "core/base.h"

struct libusb_context;

namespace frusta {

struct UsbDeviceInfo {
  int32_t vendor_id = 0, product_id = 0;
  int32_t bus = 0, address = 0;
};

class UsbWatch {
 public:
  UsbWatch();
  ~UsbWatch();
  UsbWatch(const UsbWatch&) = delete;
  UsbWatch& operator=(const UsbWatch&) = delete;

  // FRUSTA_ERROR_IO when libusb cannot start (its message says why).
  frusta_result enumerate(std::vector<UsbDeviceInfo>* out);
  // Starts counting arrivals and departures. FRUSTA_ERROR_IO where libusb has no
  // hot-plug on this platform (then a host polls enumerate).
  frusta_result watch_hotplug();
  // Handles pending hot-plug events for up to timeout_us; returns arrivals and
  // departures seen since the last call.
  int32_t poll_changes(int64_t timeout_us);

 private:
  frusta_result ensure_context();

  libusb_context* context_ = nullptr;
  int init_error_ = 0;
  bool watching_ = false;
  int hotplug_handle_ = 0;
  int32_t changes_ = 0;
};

}  // namespace frusta
