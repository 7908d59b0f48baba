// SPDX-License-Identifier: MIT
#include "devices/hid_stream.h"

#include <hidapi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <cwchar>
#include <mutex>

#include "core/error.h"

namespace frusta {

namespace hid_reports {

size_t pack(const uint8_t* data, size_t size, uint8_t report[kReportSize]) {
  const size_t count = std::min(size, kMaxChunk);
  report[0] = static_cast<uint8_t>(count);
  std::memcpy(report + 1, data, count);
  std::memset(report + 1 + count, 0, kMaxChunk - count);
  return count;
}

bool unpack(const uint8_t* report, size_t length, const uint8_t** bytes, size_t* count) {
  if (length == 0 || report[0] > length - 1) return false;
  *bytes = report + 1;
  *count = report[0];
  return true;
}

}  // namespace hid_reports

namespace {

std::string narrow(const wchar_t* text) {
  std::string out;
  for (; text != nullptr && *text != 0; ++text)
    out += *text > 0x1f && *text < 0x7f ? static_cast<char>(*text) : '?';
  return out;
}

std::string describe(uint16_t vendor_id, uint16_t product_id, const std::string& serial) {
  char ids[16];
  std::snprintf(ids, sizeof ids, "%04x:%04x", vendor_id, product_id);
  return "hid " + std::string(ids) + (serial.empty() ? "" : ":" + serial);
}

}  // namespace

void ensure_hid_initialised() {
  static std::once_flag once;
  std::call_once(once, [] { hid_init(); });
}

HidStream::HidStream(uint16_t vendor_id, uint16_t product_id, std::string serial_number)
    : vendor_id_(vendor_id),
      product_id_(product_id),
      serial_number_(std::move(serial_number)),
      name_(describe(vendor_id_, product_id_, serial_number_)) {}

HidStream::~HidStream() { close(); }

frusta_result HidStream::open() {
  close();
  ensure_hid_initialised();
  const std::wstring serial(serial_number_.begin(), serial_number_.end());  // ids are ASCII
  device_ = hid_open(vendor_id_, product_id_, serial.empty() ? nullptr : serial.c_str());
  if (device_ == nullptr)
    return fail(FRUSTA_ERROR_IO, "%s: cannot open: %s", name_.c_str(),
                narrow(hid_error(nullptr)).c_str());
  pending_begin_ = pending_end_ = 0;
  return FRUSTA_OK;
}

void HidStream::close() {
  if (device_ != nullptr) hid_close(device_);
  device_ = nullptr;
}

IoStatus HidStream::read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) {
  *received = 0;
  if (device_ == nullptr) return IoStatus::kDisconnected;
  if (pending_begin_ == pending_end_) {
    uint8_t report[hid_reports::kReportSize];
    // hidapi waits in whole milliseconds: round up, so a short wait is still a wait
    const int timeout_ms = static_cast<int>(std::min<int64_t>((timeout_us + 999) / 1000, 1000));
    const int n = hid_read_timeout(device_, report, sizeof report, timeout_ms);
    if (n < 0) return IoStatus::kDisconnected;  // hidraw fails reads once the glove is gone
    const uint8_t* bytes = nullptr;
    size_t count = 0;
    if (n == 0 || !hid_reports::unpack(report, static_cast<size_t>(n), &bytes, &count))
      return IoStatus::kOk;
    std::memcpy(pending_.data(), bytes, count);
    pending_begin_ = 0;
    pending_end_ = count;
  }
  const size_t n = std::min(capacity, pending_end_ - pending_begin_);
  std::memcpy(buffer, pending_.data() + pending_begin_, n);
  pending_begin_ += n;
  *received = n;
  return IoStatus::kOk;
}

IoStatus HidStream::write(const uint8_t* data, size_t size, bool* dropped) {
  *dropped = false;
  if (device_ == nullptr) return IoStatus::kDisconnected;
  while (size > 0) {
    uint8_t report[1 + hid_reports::kReportSize];
    report[0] = 0;  // no report ids: hidapi wants a zero first
    const size_t count = hid_reports::pack(data, size, report + 1);
    if (hid_write(device_, report, sizeof report) < 0) return IoStatus::kDisconnected;
    data += count;
    size -= count;
  }
  return IoStatus::kOk;
}

}  // namespace frusta
