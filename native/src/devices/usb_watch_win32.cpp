// SPDX-License-Identifier: MIT
#include "devices/usb_watch.h"

#define WIN32_LEAN_AND_MEAN
#include <windows.h>
// after windows.h
#include <setupapi.h>

#include <algorithm>
#include <cwchar>
#include <utility>

#include "core/error.h"

namespace frusta {

UsbWatch::UsbWatch(std::string sysfs_devices) : sysfs_devices_(std::move(sysfs_devices)) {}

UsbWatch::~UsbWatch() = default;

frusta_result UsbWatch::enumerate(std::vector<UsbDeviceInfo>* out) {
  out->clear();
  HDEVINFO set = SetupDiGetClassDevsW(nullptr, L"USB", nullptr, DIGCF_ALLCLASSES | DIGCF_PRESENT);
  if (set == INVALID_HANDLE_VALUE)
    return fail(FRUSTA_ERROR_IO, "SetupAPI cannot list USB devices (error %lu)", GetLastError());
  SP_DEVINFO_DATA data{};
  data.cbSize = sizeof data;
  for (DWORD i = 0; SetupDiEnumDeviceInfo(set, i, &data); ++i) {
    // "USB\VID_046D&PID_C52B\..."; a composite device's interfaces add "&MI_nn", root
    // hubs have no VID: neither is a device of its own
    wchar_t id[512];
    if (!SetupDiGetDeviceInstanceIdW(set, &data, id, 512, nullptr)) continue;
    unsigned vendor = 0, product = 0;
    if (std::swscanf(id, L"USB\\VID_%4x&PID_%4x", &vendor, &product) != 2 || std::wcsstr(id, L"&MI_"))
      continue;
    // where it is plugged in: "Port_#0002.Hub_#0001"; without one it has no usb: name
    wchar_t where[128] = {};
    unsigned port = 0, hub = 0;
    if (!SetupDiGetDeviceRegistryPropertyW(set, &data, SPDRP_LOCATION_INFORMATION, nullptr,
                                           reinterpret_cast<BYTE*>(where), sizeof where - sizeof(wchar_t),
                                           nullptr) ||
        std::swscanf(where, L"Port_#%u.Hub_#%u", &port, &hub) != 2)
      continue;
    out->push_back(UsbDeviceInfo{static_cast<int32_t>(vendor), static_cast<int32_t>(product),
                                 static_cast<int32_t>(hub), static_cast<int32_t>(port)});
  }
  SetupDiDestroyDeviceInfoList(set);
  std::sort(out->begin(), out->end(), [](const UsbDeviceInfo& a, const UsbDeviceInfo& b) {
    return a.bus != b.bus ? a.bus < b.bus : a.address < b.address;
  });
  return FRUSTA_OK;
}

frusta_result UsbWatch::watch_hotplug() {
  return fail(FRUSTA_ERROR_IO, "no hot-plug on this platform: poll the device list");
}

int32_t UsbWatch::poll_changes(int64_t) { return 0; }

int32_t count_usb_uevents(const char*, size_t) { return 0; }  // Linux's uevents only

}  // namespace frusta
