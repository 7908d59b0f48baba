// SPDX-License-Identifier: MIT
#include "devices/device_enumeration.h"

#include <hidapi.h>

#include <cstdio>
#include <cwchar>

#include "devices/hid_stream.h"
#include "devices/serial_ports.h"
#include "devices/usb_watch.h"
#include "core/base.h"

namespace frusta {

namespace {

std::string narrow(const wchar_t* text) {
  std::string out;
  for (; text != nullptr && *text != 0; ++text)
    if (*text > 0x20 && *text < 0x7f) out += static_cast<char>(*text);  // ids are ASCII
  return out;
}

}  // namespace

void enumerate_devices(std::vector<DeviceInfo>* out) {
  out->clear();
  list_serial_ports(out);

  ensure_hid_initialised();
  hid_device_info* devices = hid_enumerate(0, 0);
  for (const hid_device_info* d = devices; d != nullptr; d = d->next) {
    if (d->usage_page < 0xFF00) continue;  // our profile uses vendor-defined reports
    char uri[64];
    std::snprintf(uri, sizeof uri, "hid:%04x:%04x", d->vendor_id, d->product_id);
    const std::string serial = narrow(d->serial_number);
    out->push_back(DeviceInfo{FRUSTA_DEVICE_KIND_HID, d->vendor_id, d->product_id,
                              serial.empty() ? uri : std::string(uri) + ":" + serial});
  }
  hid_free_enumeration(devices);

  UsbWatch usb;
  std::vector<UsbDeviceInfo> usb_devices;
  if (usb.enumerate(&usb_devices) == FRUSTA_OK) {
    for (const UsbDeviceInfo& d : usb_devices) {
      char uri[32];
      std::snprintf(uri, sizeof uri, "usb:%d:%d", d.bus, d.address);
      out->push_back(DeviceInfo{FRUSTA_DEVICE_KIND_USB, d.vendor_id, d.product_id, uri});
    }
  }
}

}  // namespace frusta
