// SPDX-License-Identifier: MIT
#include "devices/usb_watch.h"

#include <libusb.h>

#include <algorithm>

#include "core/error.h"

namespace frusta {

namespace {

// user_data is the watch's change count
int LIBUSB_CALL count_change(libusb_context*, libusb_device*, libusb_hotplug_event, void* changes) {
  ++*static_cast<int32_t*>(changes);
  return 0;  // stay registered
}

}  // namespace

UsbWatch::UsbWatch() = default;

UsbWatch::~UsbWatch() {
  if (context_ == nullptr) return;
  if (watching_) libusb_hotplug_deregister_callback(context_, hotplug_handle_);
  libusb_exit(context_);
}

frusta_result UsbWatch::ensure_context() {
  if (context_ != nullptr) return FRUSTA_OK;
  if (init_error_ == 0) init_error_ = libusb_init(&context_);
  if (init_error_ == 0) return FRUSTA_OK;
  context_ = nullptr;
  return fail(FRUSTA_ERROR_IO, "libusb cannot start: %s", libusb_strerror(init_error_));
}

frusta_result UsbWatch::enumerate(std::vector<UsbDeviceInfo>* out) {
  out->clear();
  if (frusta_result r = ensure_context()) return r;
  libusb_device** list = nullptr;
  const ssize_t count = libusb_get_device_list(context_, &list);
  if (count < 0)
    return fail(FRUSTA_ERROR_IO, "libusb cannot list devices: %s",
                libusb_strerror(static_cast<int>(count)));
  for (ssize_t i = 0; i < count; ++i) {
    libusb_device_descriptor descriptor{};
    if (libusb_get_device_descriptor(list[i], &descriptor) != 0) continue;
    out->push_back(UsbDeviceInfo{descriptor.idVendor, descriptor.idProduct,
                                 libusb_get_bus_number(list[i]), libusb_get_device_address(list[i])});
  }
  libusb_free_device_list(list, 1);
  std::sort(out->begin(), out->end(), [](const UsbDeviceInfo& a, const UsbDeviceInfo& b) {
    return a.bus != b.bus ? a.bus < b.bus : a.address < b.address;
  });
  return FRUSTA_OK;
}

frusta_result UsbWatch::watch_hotplug() {
  if (watching_) return FRUSTA_OK;
  if (frusta_result r = ensure_context()) return r;
  if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG))
    return fail(FRUSTA_ERROR_IO, "libusb has no hot-plug on this platform: poll the device list");
  const int events = LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED | LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT;
  const int error = libusb_hotplug_register_callback(
      context_, static_cast<libusb_hotplug_event>(events), LIBUSB_HOTPLUG_NO_FLAGS,
      LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY, count_change,
      &changes_, &hotplug_handle_);
  if (error != LIBUSB_SUCCESS)
    return fail(FRUSTA_ERROR_IO, "libusb refused a hot-plug watch: %s", libusb_strerror(error));
  watching_ = true;
  return FRUSTA_OK;
}

int32_t UsbWatch::poll_changes(int64_t timeout_us) {
  if (watching_) {
    timeval timeout{};  // its fields' types differ between POSIX and Winsock
    timeout.tv_sec = static_cast<decltype(timeout.tv_sec)>(timeout_us / 1000000);
    timeout.tv_usec = static_cast<decltype(timeout.tv_usec)>(timeout_us % 1000000);
    libusb_handle_events_timeout_completed(context_, &timeout, nullptr);
  }
  const int32_t changes = changes_;
  changes_ = 0;
  return changes;
}

}  // namespace frusta
