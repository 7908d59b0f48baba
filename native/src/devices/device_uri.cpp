// SPDX-License-Identifier: MIT
#include "devices/device_uri.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "devices/serial_stream.h"

namespace frusta {

namespace {

// a hexadecimal USB id, 1 to 4 digits
bool parse_usb_id(std::string_view text, uint16_t* out) {
  if (text.empty() || text.size() > 4) return false;
  uint32_t value = 0;
  for (char c : text) {
    const int digit = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
    if (digit < 0) return false;
    value = value * 16 + static_cast<uint32_t>(digit);
  }
  *out = static_cast<uint16_t>(value);
  return true;
}

// the URI quoted up to kQuoted characters: a long one would push the reason out of the
// thread's message
constexpr size_t kQuoted = 96;

frusta_result bad(std::string_view uri, const char* why) {
  return fail(FRUSTA_ERROR_OUT_OF_RANGE, "device URI \"%.*s%s\": %s",
              static_cast<int>(std::min(uri.size(), kQuoted)), uri.data(),
              uri.size() > kQuoted ? "..." : "", why);
}

}  // namespace

frusta_result parse_device_uri(std::string_view uri, DeviceAddress* out) {
  const size_t colon = uri.find(':');
  if (colon == std::string_view::npos)
    return bad(uri, "no scheme; expected opengloves:, serial:, hid: or replay:");
  const std::string_view scheme = uri.substr(0, colon);
  std::string_view rest = uri.substr(colon + 1);
  std::string_view query;
  if (const size_t q = rest.find('?'); q != std::string_view::npos) {
    query = rest.substr(q + 1);
    rest = rest.substr(0, q);
  }
  DeviceAddress a;
  if (scheme == "opengloves" || scheme == "serial") {
    a.kind = scheme == "opengloves" ? DeviceKind::kOpenGloves : DeviceKind::kSerial;
  } else if (scheme == "hid") {
    a.kind = DeviceKind::kHid;
  } else if (scheme == "replay") {
    a.kind = DeviceKind::kReplay;
  } else {
    return bad(uri, "unknown scheme; expected opengloves:, serial:, hid: or replay:");
  }
  if (rest.empty()) return bad(uri, "no device path after the scheme");

  if (a.kind == DeviceKind::kHid) {
    const size_t first = rest.find(':');
    const size_t second = first == std::string_view::npos ? first : rest.find(':', first + 1);
    if (first == std::string_view::npos || !parse_usb_id(rest.substr(0, first), &a.vendor_id) ||
        !parse_usb_id(rest.substr(first + 1, second == std::string_view::npos ? second : second - first - 1),
                      &a.product_id))
      return bad(uri, "expected hid:VID:PID[:SERIAL] with hexadecimal ids (hid:1209:a7e1)");
    if (second != std::string_view::npos) a.serial_number = std::string(rest.substr(second + 1));
  } else {
    a.path = std::string(rest);
  }

  // parameters: name=value joined by '&'
  while (!query.empty()) {
    const size_t amp = query.find('&');
    const std::string_view item = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos) return bad(uri, "a parameter without '=' (name=value)");
    const std::string_view name = item.substr(0, eq);
    const std::string value(item.substr(eq + 1));
    const bool serial = a.kind == DeviceKind::kOpenGloves || a.kind == DeviceKind::kSerial;
    if (name == "record" && !value.empty()) {
      a.record_path = value;
    } else if (name == "baud" && serial) {
      char* end = nullptr;
      errno = 0;
      const long long baud = std::strtoll(value.c_str(), &end, 10);
      // range first: 2^32 + 115200 once became 115200 on its way to an int32
      if (value.empty() || *end != '\0' || errno == ERANGE || baud < 1 || baud > INT32_MAX ||
          !is_supported_baud(static_cast<int32_t>(baud)))
        return bad(uri, "baud is not a rate termios supports (9600 ... 115200 ... 2000000)");
      a.baud = static_cast<int32_t>(baud);
    } else if (name == "speed" && a.kind == DeviceKind::kReplay && (value == "1" || value == "max")) {
      a.real_time = value == "1";
    } else if (name == "loop" && a.kind == DeviceKind::kReplay && (value == "0" || value == "1")) {
      a.loop = value == "1";
    } else {
      return bad(uri, "unknown parameter or value for this scheme (serial: baud; replay: "
                      "speed=1|max, loop=0|1; any: record=FILE)");
    }
  }
  *out = a;
  return FRUSTA_OK;
}

}  // namespace frusta
