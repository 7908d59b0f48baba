// SPDX-License-Identifier: MIT
// Where the kernel offers /dev/uhid, a virtual HID glove the real hidapi hidraw backend
// drives end to end. Machines without /dev/uhid (this one) say so and skip.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/input.h>
#include <linux/uhid.h>
#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include "core/error.h"
#include "devices/device_link.h"
#include "devices/frusta_protocol.h"
#include "devices/hid_stream.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "runtime/world.h"
#include "scenes/binary_glove.h"

namespace frusta {
namespace {

namespace bp = binary_profile;
constexpr uint16_t kVendor = 0x1209, kProduct = 0xF5F5;  // pid.codes' test range

// A HID glove made by the kernel's uhid: one vendor-defined 64-byte input and output
// report, the binary profile inside as binary_profile.md's "Over HID" says.
class UhidGlove {
 public:
  static bool available() { return access("/dev/uhid", R_OK | W_OK) == 0; }

  explicit UhidGlove(scenes::BinaryGlove& firmware) : firmware_(firmware) {
    fd_ = open("/dev/uhid", O_RDWR | O_CLOEXEC);
    uhid_event ev{};
    ev.type = UHID_CREATE2;
    std::strcpy(reinterpret_cast<char*>(ev.u.create2.name), "Frusta test glove");
    std::strcpy(reinterpret_cast<char*>(ev.u.create2.uniq), "FR-0042");
    static const uint8_t kDescriptor[] = {
        0x06, 0x00, 0xFF,  // usage page: vendor defined
        0x09, 0x01, 0xA1, 0x01,  // usage 1, application collection
        0x15, 0x00, 0x26, 0xFF, 0x00, 0x75, 0x08,  // bytes 0..255
        0x95, 0x40, 0x09, 0x01, 0x81, 0x02,  // 64 of them in
        0x95, 0x40, 0x09, 0x01, 0x91, 0x02,  // 64 of them out
        0xC0};
    std::memcpy(ev.u.create2.rd_data, kDescriptor, sizeof kDescriptor);
    ev.u.create2.rd_size = sizeof kDescriptor;
    ev.u.create2.bus = BUS_USB;
    ev.u.create2.vendor = kVendor;
    ev.u.create2.product = kProduct;
    created_ = fd_ >= 0 && write(fd_, &ev, sizeof ev) == static_cast<ssize_t>(sizeof ev);
    if (created_) thread_ = std::thread([this] { run(); });
  }
  ~UhidGlove() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (fd_ >= 0) {
      uhid_event ev{};
      ev.type = UHID_DESTROY;
      (void)!write(fd_, &ev, sizeof ev);
      close(fd_);
    }
  }
  bool created() const { return created_; }

 private:
  void run() {
    const scenes::SimulatedGlove::Firmware sample = firmware_.firmware();
    const scenes::SimulatedGlove::Listener listen = firmware_.listener();
    auto next = std::chrono::steady_clock::now();
    for (int64_t tick = 0; !stop_;) {
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 1) > 0) {
        uhid_event ev{};
        if (read(fd_, &ev, sizeof ev) > 0 && ev.type == UHID_OUTPUT) {
          // hidraw hands uhid the report as written, report-id byte (0) first
          const uint8_t* report = ev.u.output.data;
          size_t size = ev.u.output.size;
          if (size == hid_reports::kReportSize + 1) ++report, --size;
          const uint8_t* bytes = nullptr;
          size_t count = 0;
          if (hid_reports::unpack(report, size, &bytes, &count))
            listen(std::string(reinterpret_cast<const char*>(bytes), count));
        }
      }
      if (std::chrono::steady_clock::now() < next) continue;
      next += std::chrono::milliseconds(2);  // 500 Hz
      const std::string bytes = sample(tick++);
      for (size_t at = 0; at < bytes.size();) {
        uhid_event ev{};
        ev.type = UHID_INPUT2;
        at += hid_reports::pack(reinterpret_cast<const uint8_t*>(bytes.data()) + at,
                                bytes.size() - at, ev.u.input2.data);
        ev.u.input2.size = hid_reports::kReportSize;
        (void)!write(fd_, &ev, sizeof ev);
      }
    }
  }

  scenes::BinaryGlove& firmware_;
  int fd_ = -1;
  bool created_ = false;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST(hidStream, AVirtualHidGloveHandshakesAndReadsCommandsBack) {
  if (!UhidGlove::available())
    GTEST_SKIP() << "no /dev/uhid on this machine (the kernel lacks it or it is not ours to "
                    "use): the HID device part is skipped; the report packing and hidapi's "
                    "open of an absent glove ran above";
  DeviceCapabilities caps;
  caps.input_rate_hz = 500.0;
  caps.output_rate_hz = 500.0;
  scenes::BinaryGlove firmware(caps);
  UhidGlove uhid(firmware);
  ASSERT_TRUE(uhid.created()) << std::strerror(errno);

  World world{WorldDef{}};
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  ASSERT_EQ(world.start(), FRUSTA_OK);
  DeviceLinkDef def;
  def.host_timeout_s = 0.0;
  DeviceLink link(world.port(hand.slot), def, std::make_unique<HidStream>(kVendor, kProduct, "FR-0042"),
                  std::make_unique<FrustaProtocol>());
  // the kernel adds the hidraw node in its own time: open once it is there (the
  // deadline only turns a hang into a failure)
  const auto until = [](const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!done()) {
      if (std::chrono::steady_clock::now() > end) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  };
  ASSERT_TRUE(until([&] { return link.open() == FRUSTA_OK; })) << frusta::last_error_message();
  DeviceLinkStatus s;
  ASSERT_TRUE(until([&] {
    s = link.status();
    return s.capabilities.protocol_version != 0 && s.frames_ok >= 2;
  }));
  EXPECT_EQ(s.capabilities.protocol_version, bp::kVersion);
  EXPECT_DOUBLE_EQ(s.input_rate_hz, 500.0) << "by the glove's stamps";
  EXPECT_TRUE(until([&] { return firmware.commands().size() > 100u; }));
  link.close();
  world.stop();
}

}  // namespace
}  // namespace frusta
