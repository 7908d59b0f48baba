// SPDX-License-Identifier: MIT
// The serial drivers (USB CDC, FTDI, Bluetooth SPP) each register their COM ports
// under HKLM\HARDWARE\DEVICEMAP\SERIALCOMM while the port exists: the list the system
// keeps of present ports.
#include "devices/serial_ports.h"

#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/base.h"

namespace frusta {

namespace {

int port_number(const std::string& name) {
  return name.rfind("COM", 0) == 0 ? std::atoi(name.c_str() + 3) : 0;
}

}  // namespace

void list_serial_ports(std::vector<DeviceInfo>* out) {
  HKEY key = nullptr;
  if (RegOpenKeyExA(HKEY_LOCAL_MACHINE, "HARDWARE\\DEVICEMAP\\SERIALCOMM", 0, KEY_READ, &key) !=
      ERROR_SUCCESS)
    return;  // no serial driver has registered a port
  std::vector<std::string> ports;
  for (DWORD index = 0;; ++index) {
    char value_name[256];
    DWORD name_size = sizeof value_name;
    BYTE data[64] = {};
    DWORD data_size = sizeof data - 1;
    DWORD type = 0;
    const LONG result =
        RegEnumValueA(key, index, value_name, &name_size, nullptr, &type, data, &data_size);
    if (result == ERROR_NO_MORE_ITEMS) break;
    if (result == ERROR_SUCCESS && type == REG_SZ)
      ports.emplace_back(reinterpret_cast<const char*>(data));
  }
  RegCloseKey(key);
  // COM3 before COM10
  std::sort(ports.begin(), ports.end(), [](const std::string& a, const std::string& b) {
    return port_number(a) != port_number(b) ? port_number(a) < port_number(b) : a < b;
  });
  for (const std::string& port : ports)
    out->push_back(DeviceInfo{FRUSTA_DEVICE_KIND_SERIAL, -1, -1, "serial:" + port});
}

}  // namespace frusta
