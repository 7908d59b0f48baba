// SPDX-License-Identifier: MIT
#include "devices/serial_ports.h"

#include <dirent.h>

#include <algorithm>
#include <string>

#include "core/base.h"

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

}  // namespace

void list_serial_ports(std::vector<DeviceInfo>* out) {
  add_serial_ports("/dev/serial/by-id", true, out);  // stable across replugs: first
  add_serial_ports("/dev", false, out);
}

}  // namespace frusta
