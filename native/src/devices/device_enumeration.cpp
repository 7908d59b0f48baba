// SPDX-License-Identifier: MIT
#include "devices/device_enumeration.h"

#include <dirent.h>
#include <hidapi.h>

#include <algorithm>
#include <cstdio>
#include <cwchar>

#include "devices/hid_stream.h"
#include "devices/usb_watch.h"
#include "frusta/frusta.h"

namespace frusta {

namespace {

// the names serial gloves show up under
bool is_serial_name(const std::string& name) {
  for (const char* prefix : {"ttyACM", "ttyUSB", "rfcomm"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

void add_serial_ports(const std::string& folder, bool all, std::vector<DeviceInfo>* out) {
  DIR* dir = opendir(folder.c_str());
  if (dir == nullptr) return;
  std::vector<std::string> names;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name[0] != '.' && (all || is_serial_name(name))) names.push_back(name);
  }
  closedir(dir);
  std::sort(names.begin(), names.end());
  for (const std::string& name : names)
    out->push_back(DeviceInfo{FRUSTA_DEVICE_KIND_SERIAL, -1, -1, "serial:" + folder + "/" + name});
}

std::string narrow(const wchar_t* text) {
  std::string out;
  for (; text != nullptr && *text != 0; ++text)
    if (*text > 0x20 && *text < 0x7f) out += static_cast<char>(*text);  // ids are ASCII
  return out;
}

}  // namespace

void enumerate_devices(std::vector<DeviceInfo>* out) {
  out->clear();
  add_serial_ports("/dev/serial/by-id", true, out);  // stable across replugs: first
  add_serial_ports("/dev", false, out);

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
