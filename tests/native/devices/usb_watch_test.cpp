// SPDX-License-Identifier: MIT
// UsbWatch on the platform's own API: it lists what the bus has (nothing on this
// machine, which has no USB bus, but the call is the real one), reads sysfs as Linux
// lays it out (a folder of its own here), counts only whole devices coming and going
// in the kernel's uevents, and its hot-plug watch is either running or refused with a
// reason, never silently absent.
#include "devices/usb_watch.h"

#include <gtest/gtest.h>
#if defined(__linux__)
#include <unistd.h>  // getpid
#endif

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace frusta {
namespace {

TEST(usbWatch, ListsTheBusInOrder) {
  UsbWatch watch;
  std::vector<UsbDeviceInfo> devices(3);  // stale contents are replaced
  ASSERT_EQ(watch.enumerate(&devices), FRUSTA_OK) << frusta::last_error_message();
  for (size_t i = 0; i < devices.size(); ++i) {
    EXPECT_GT(devices[i].bus, 0);
    EXPECT_GE(devices[i].vendor_id, 0);
    EXPECT_LE(devices[i].vendor_id, 0xFFFF);
    if (i > 0) {
      EXPECT_TRUE(devices[i - 1].bus < devices[i].bus || devices[i - 1].address < devices[i].address);
    }
  }
  std::vector<UsbDeviceInfo> again;
  ASSERT_EQ(watch.enumerate(&again), FRUSTA_OK);
  EXPECT_EQ(again.size(), devices.size()) << "nothing was plugged in between";
}

TEST(usbWatch, HotplugIsWatchedOrRefusedWithAReason) {
  UsbWatch watch;
  const frusta_result r = watch.watch_hotplug();
  if (r == FRUSTA_OK) {
    EXPECT_EQ(watch.watch_hotplug(), FRUSTA_OK) << "a second call is harmless";
  } else {
    ASSERT_EQ(r, FRUSTA_ERROR_IO);
    EXPECT_NE(std::string(frusta::last_error_message()).find("hot-plug"), std::string::npos);
  }
  EXPECT_EQ(watch.poll_changes(20000), 0) << "nobody plugged anything in";
}

#if defined(__linux__)
namespace fs = std::filesystem;

void write(const fs::path& file, const char* text) { std::ofstream(file) << text; }

// a device folder as the kernel writes one
void device(const fs::path& root, const char* name, const char* vendor, const char* product,
            const char* bus, const char* number) {
  fs::create_directories(root / name);
  write(root / name / "idVendor", vendor);
  write(root / name / "idProduct", product);
  write(root / name / "busnum", bus);
  write(root / name / "devnum", number);
}

TEST(usbWatch, ReadsSysfsDevicesNotTheirInterfaces) {
  const fs::path root = fs::temp_directory_path() / ("frusta_usb_sysfs_" + std::to_string(::getpid()));
  fs::remove_all(root);
  device(root, "usb2", "1d6b\n", "0003\n", "2\n", "1\n");       // a root hub is a device too
  device(root, "1-1.4", "1209\n", "a1f0\n", "1\n", "7\n");      // a glove
  device(root, "1-1", "05e3\n", "0610\n", "1\n", "2\n");        // the hub it is on
  fs::create_directories(root / "1-1.4:1.0");                   // its interface: no ids
  write(root / "1-1.4:1.0" / "bInterfaceClass", "03\n");
  device(root, "3-1", "zz\n", "0001\n", "3\n", "2\n");          // unreadable: left out
  std::vector<UsbDeviceInfo> devices;
  ASSERT_EQ(UsbWatch(root.string()).enumerate(&devices), FRUSTA_OK) << frusta::last_error_message();
  ASSERT_EQ(devices.size(), 3u);
  EXPECT_EQ(devices[0].vendor_id, 0x05e3);
  EXPECT_EQ(devices[0].address, 2);
  EXPECT_EQ(devices[1].vendor_id, 0x1209);
  EXPECT_EQ(devices[1].product_id, 0xa1f0);
  EXPECT_EQ(devices[1].bus, 1);
  EXPECT_EQ(devices[1].address, 7);
  EXPECT_EQ(devices[2].bus, 2);
  fs::remove_all(root);

  // no USB bus at all: nothing, not an error
  ASSERT_EQ(UsbWatch((root / "absent").string()).enumerate(&devices), FRUSTA_OK);
  EXPECT_TRUE(devices.empty());
}

TEST(usbWatch, CountsWholeDevicesArrivingAndLeaving) {
  auto count = [](const std::string& message) { return count_usb_uevents(message.data(), message.size()); };
  using namespace std::string_literals;
  EXPECT_EQ(count("add@/devices/pci0000:00/usb1/1-1\0ACTION=add\0SUBSYSTEM=usb\0DEVTYPE=usb_device\0"s), 1);
  EXPECT_EQ(count("remove@/devices/pci0000:00/usb1/1-1\0ACTION=remove\0DEVTYPE=usb_device\0SUBSYSTEM=usb\0"s), 1);
  // its interface, a change, another subsystem, a truncated datagram, nothing
  EXPECT_EQ(count("add@/devices/pci0000:00/usb1/1-1/1-1:1.0\0SUBSYSTEM=usb\0DEVTYPE=usb_interface\0"s), 0);
  EXPECT_EQ(count("change@/devices/pci0000:00/usb1/1-1\0SUBSYSTEM=usb\0DEVTYPE=usb_device\0"s), 0);
  EXPECT_EQ(count("add@/devices/virtual/hidraw/hidraw3\0SUBSYSTEM=hidraw\0"s), 0);
  EXPECT_EQ(count("add@/devices/pci0000:00/usb1/1-1\0SUBSYSTEM=us"s), 0);
  EXPECT_EQ(count_usb_uevents(nullptr, 0), 0);
}
#endif

}  // namespace
}  // namespace frusta
