// SPDX-License-Identifier: MIT
// libusb through UsbWatch: it starts, lists what the bus has (nothing on this
// machine, which has no /dev/bus/usb, but the call is the real one), and its hot-plug
// watch is either running or refused with a reason, never silently absent.
#include "devices/usb_watch.h"

#include <gtest/gtest.h>
#include <libusb.h>

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

TEST(usbWatch, HotplugIsWatchedWhereLibusbCanAndRefusedWithAReasonWhereNot) {
  UsbWatch watch;
  const frusta_result r = watch.watch_hotplug();
  if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
    ASSERT_EQ(r, FRUSTA_OK) << frusta::last_error_message();
    EXPECT_EQ(watch.watch_hotplug(), FRUSTA_OK) << "a second call is harmless";
  } else {
    ASSERT_EQ(r, FRUSTA_ERROR_IO);
    EXPECT_NE(std::string(frusta::last_error_message()).find("hot-plug"), std::string::npos);
  }
  EXPECT_EQ(watch.poll_changes(20000), 0) << "nobody plugged anything in";
}

}  // namespace
}  // namespace frusta
