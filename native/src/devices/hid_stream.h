// SPDX-License-Identifier: MIT
// Our binary profile over HID (binary_profile.md, "Over HID"): a glove with one
// vendor-defined 64-byte input report and one 64-byte output report, no report ids.
// Each report carries up to 63 bytes of the profile's byte stream: byte 0 is how
// many, the rest zero padding. Frames may span reports; the profile's framing and CRC
// do the rest, as over serial. Through hidapi's hidraw backend.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "devices/byte_stream.h"

struct hid_device_;

namespace frusta {

namespace hid_reports {

constexpr size_t kReportSize = 64;
constexpr size_t kMaxChunk = kReportSize - 1;

// Fills one report with the first bytes of data (at most kMaxChunk); returns how many.
size_t pack(const uint8_t* data, size_t size, uint8_t report[kReportSize]);
// The bytes a report of `length` bytes carries; false when its count claims more
// than the report holds (the report is dropped).
bool unpack(const uint8_t* report, size_t length, const uint8_t** bytes, size_t* count);

}  // namespace hid_reports

// hid_init once per process, from whichever thread first needs hidapi.
void ensure_hid_initialised();

class HidStream final : public ByteStream {
 public:
  // serial_number empty: the first device with these ids.
  HidStream(uint16_t vendor_id, uint16_t product_id, std::string serial_number);
  ~HidStream() override;

  frusta_result open() override;
  void close() override;
  bool is_open() const override { return device_ != nullptr; }
  IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) override;
  IoStatus write(const uint8_t* data, size_t size, bool* dropped) override;
  const std::string& name() const override { return name_; }

 private:
  uint16_t vendor_id_, product_id_;
  std::string serial_number_;
  std::string name_;
  hid_device_* device_ = nullptr;
  // a report's bytes the caller's buffer had no room for yet
  std::array<uint8_t, hid_reports::kMaxChunk> pending_{};
  size_t pending_begin_ = 0, pending_end_ = 0;
};

}  // namespace frusta
