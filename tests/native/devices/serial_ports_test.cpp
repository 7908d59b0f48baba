// SPDX-License-Identifier: MIT
// The serial ports enumeration offers: serial: URIs a glove can be opened by, in a
// stable order. On Windows the test registers two COM ports of its own in the
// registry's SERIALCOMM, as serial drivers do (possible under Wine and as an
// administrator; skipped otherwise), and finds COM3 listed before COM10.
#include "devices/serial_ports.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
#endif

#include "frusta/frusta.h"

namespace frusta {
namespace {

TEST(serialPorts, EveryEntryIsASerialUriInAStableOrder) {
  std::vector<DeviceInfo> first, second;
  list_serial_ports(&first);
  list_serial_ports(&second);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].uri, second[i].uri);
    EXPECT_EQ(first[i].uri.rfind("serial:", 0), 0u) << first[i].uri;
    EXPECT_EQ(first[i].kind, FRUSTA_DEVICE_KIND_SERIAL);
    EXPECT_EQ(first[i].vendor_id, -1) << "a serial port has no USB ids to offer";
  }
}

#ifdef _WIN32
TEST(serialPorts, RegisteredComPortsAreListedInNumericOrder) {
  HKEY key = nullptr;
  if (RegCreateKeyExA(HKEY_LOCAL_MACHINE, "HARDWARE\\DEVICEMAP\\SERIALCOMM", 0, nullptr,
                      REG_OPTION_VOLATILE, KEY_READ | KEY_WRITE, nullptr, &key,
                      nullptr) != ERROR_SUCCESS)
    GTEST_SKIP() << "HKLM cannot be written here (not an administrator)";
  const auto add = [&](const char* device, const char* port) {
    return RegSetValueExA(key, device, 0, REG_SZ, reinterpret_cast<const BYTE*>(port),
                          static_cast<DWORD>(std::string(port).size() + 1)) == ERROR_SUCCESS;
  };
  ASSERT_TRUE(add("\\Device\\FrustaTest10", "COM10"));
  ASSERT_TRUE(add("\\Device\\FrustaTest3", "COM3"));
  std::vector<DeviceInfo> ports;
  list_serial_ports(&ports);
  RegDeleteValueA(key, "\\Device\\FrustaTest10");
  RegDeleteValueA(key, "\\Device\\FrustaTest3");
  RegCloseKey(key);

  const auto at = [&](const std::string& uri) {
    return std::find_if(ports.begin(), ports.end(),
                        [&](const DeviceInfo& d) { return d.uri == uri; }) - ports.begin();
  };
  const auto com3 = at("serial:COM3"), com10 = at("serial:COM10");
  ASSERT_LT(com3, static_cast<std::ptrdiff_t>(ports.size()));
  ASSERT_LT(com10, static_cast<std::ptrdiff_t>(ports.size()));
  EXPECT_LT(com3, com10) << "by number, not by text";
}
#endif

}  // namespace
}  // namespace frusta
