// SPDX-License-Identifier: MIT
#include "devices/usb_watch.h"

#include <dirent.h>
#include <linux/netlink.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include "core/error.h"

namespace frusta {

namespace {

// one sysfs attribute as a number (idVendor and idProduct are hex); false if absent
bool read_number(const std::string& path, int base, int32_t* out) {
  FILE* file = std::fopen(path.c_str(), "r");
  if (file == nullptr) return false;
  char text[32] = {};
  const bool read = std::fgets(text, sizeof text, file) != nullptr;
  std::fclose(file);
  if (!read) return false;
  char* end = nullptr;
  const long value = std::strtol(text, &end, base);
  if (end == text || value < 0 || value > 0xFFFF) return false;
  *out = static_cast<int32_t>(value);
  return true;
}

}  // namespace

UsbWatch::UsbWatch(std::string sysfs_devices) : sysfs_devices_(std::move(sysfs_devices)) {}

UsbWatch::~UsbWatch() {
  if (netlink_ >= 0) close(netlink_);
}

frusta_result UsbWatch::enumerate(std::vector<UsbDeviceInfo>* out) {
  out->clear();
  DIR* dir = opendir(sysfs_devices_.c_str());
  if (dir == nullptr) {
    if (errno == ENOENT) return FRUSTA_OK;  // no USB bus on this system
    return fail(FRUSTA_ERROR_IO, "cannot list USB devices in %s: %s", sysfs_devices_.c_str(),
                std::strerror(errno));
  }
  // devices ("1-1.2", "usb1") have these; their interfaces ("1-1.2:1.0") do not
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    const std::string folder = sysfs_devices_ + "/" + entry->d_name + "/";
    UsbDeviceInfo d;
    if (read_number(folder + "idVendor", 16, &d.vendor_id) &&
        read_number(folder + "idProduct", 16, &d.product_id) &&
        read_number(folder + "busnum", 10, &d.bus) && read_number(folder + "devnum", 10, &d.address))
      out->push_back(d);
  }
  closedir(dir);
  std::sort(out->begin(), out->end(), [](const UsbDeviceInfo& a, const UsbDeviceInfo& b) {
    return a.bus != b.bus ? a.bus < b.bus : a.address < b.address;
  });
  return FRUSTA_OK;
}

frusta_result UsbWatch::watch_hotplug() {
  if (netlink_ >= 0) return FRUSTA_OK;
  // the kernel's own uevents (group 1), as libusb's netlink backend listens to them
  const int fd = socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC | SOCK_NONBLOCK, NETLINK_KOBJECT_UEVENT);
  sockaddr_nl address{};
  address.nl_family = AF_NETLINK;
  address.nl_groups = 1;
  if (fd < 0 || bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    if (fd >= 0) close(fd);
    return fail(FRUSTA_ERROR_IO, "no hot-plug here (the kernel's uevents: %s): poll the device list",
                std::strerror(error));
  }
  netlink_ = fd;
  return FRUSTA_OK;
}

int32_t UsbWatch::poll_changes(int64_t timeout_us) {
  if (netlink_ < 0) return 0;
  int32_t changes = 0;
  pollfd ready{netlink_, POLLIN, 0};
  int wait_ms = static_cast<int>(std::min<int64_t>((std::max<int64_t>(timeout_us, 0) + 999) / 1000, 1 << 30));
  while (poll(&ready, 1, wait_ms) > 0) {
    char data[8192];
    sockaddr_nl sender{};
    iovec part{data, sizeof data};
    msghdr message{};
    message.msg_name = &sender;
    message.msg_namelen = sizeof sender;
    message.msg_iov = &part;
    message.msg_iovlen = 1;
    const ssize_t size = recvmsg(netlink_, &message, 0);
    if (size <= 0) break;
    if (sender.nl_pid == 0) changes += count_usb_uevents(data, static_cast<size_t>(size));  // the kernel's only
    wait_ms = 0;  // then whatever else is already queued
  }
  return changes;
}

int32_t count_usb_uevents(const char* data, size_t size) {
  // "add@/devices/...\0ACTION=add\0SUBSYSTEM=usb\0DEVTYPE=usb_device\0..."
  bool arrive_or_leave = false, usb = false, device = false;
  for (size_t at = 0; at < size;) {
    const size_t length = strnlen(data + at, size - at);
    const std::string field(data + at, length);
    if (at == 0) arrive_or_leave = field.rfind("add@", 0) == 0 || field.rfind("remove@", 0) == 0;
    usb = usb || field == "SUBSYSTEM=usb";
    device = device || field == "DEVTYPE=usb_device";
    at += length + 1;
  }
  return arrive_or_leave && usb && device ? 1 : 0;
}

}  // namespace frusta
