// SPDX-License-Identifier: MIT
// The Win32 comm API, synchronous: the device thread is the port's only user, and
// COMMTIMEOUTS give the read the same shape as ppoll + read on POSIX.
#include "devices/serial_stream.h"

#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include "core/error.h"

namespace frusta {

namespace {

// a command the glove does not take within this is dropped, never queued behind
constexpr DWORD kWriteTimeoutMs = 2;

std::string describe_error(DWORD error) {
  char text[256] = {};
  const DWORD length =
      FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, error,
                     0, text, sizeof text, nullptr);
  std::string message(text, length);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r' ||
                              message.back() == '.'))
    message.pop_back();
  return message.empty() ? "error " + std::to_string(error) : message;
}

// COM10 and above open only through the device namespace; COM1..COM9 work either way
std::string device_path(const std::string& path) {
  return path.rfind("\\\\", 0) == 0 ? path : "\\\\.\\" + path;
}

// Read returns at once with whatever has arrived, else waits up to timeout_ms for the
// first byte (the documented MAXDWORD, MAXDWORD, constant case); 0 polls.
bool set_timeouts(HANDLE port, uint32_t read_timeout_ms) {
  COMMTIMEOUTS timeouts{};
  timeouts.ReadIntervalTimeout = MAXDWORD;
  timeouts.ReadTotalTimeoutMultiplier = read_timeout_ms > 0 ? MAXDWORD : 0;
  timeouts.ReadTotalTimeoutConstant = read_timeout_ms;
  timeouts.WriteTotalTimeoutMultiplier = 0;
  timeouts.WriteTotalTimeoutConstant = kWriteTimeoutMs;
  return SetCommTimeouts(port, &timeouts) != 0;
}

}  // namespace

SerialStream::SerialStream(std::string path, int32_t baud)
    : path_(std::move(path)), baud_(baud), name_("serial " + path_) {}

SerialStream::~SerialStream() { close(); }

bool SerialStream::is_open() const { return handle_ != nullptr; }

frusta_result SerialStream::open() {
  close();
  if (!is_supported_baud(baud_))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s: baud %d is not a supported rate", name_.c_str(),
                baud_);
  HANDLE port = CreateFileA(device_path(path_).c_str(), GENERIC_READ | GENERIC_WRITE, 0, nullptr,
                            OPEN_EXISTING, 0, nullptr);
  if (port == INVALID_HANDLE_VALUE)
    return fail(FRUSTA_ERROR_IO, "%s: cannot open: %s", name_.c_str(),
                describe_error(GetLastError()).c_str());
  DCB dcb{};
  dcb.DCBlength = sizeof dcb;
  if (!GetCommState(port, &dcb)) {
    const DWORD error = GetLastError();
    CloseHandle(port);
    return fail(FRUSTA_ERROR_IO, "%s: not a serial port: %s", name_.c_str(),
                describe_error(error).c_str());
  }
  dcb.BaudRate = static_cast<DWORD>(baud_);
  dcb.ByteSize = 8;
  dcb.Parity = NOPARITY;
  dcb.StopBits = ONESTOPBIT;
  dcb.fBinary = TRUE;
  dcb.fParity = FALSE;
  dcb.fOutxCtsFlow = FALSE;
  dcb.fOutxDsrFlow = FALSE;
  dcb.fDsrSensitivity = FALSE;
  dcb.fDtrControl = DTR_CONTROL_ENABLE;
  dcb.fRtsControl = RTS_CONTROL_ENABLE;
  dcb.fOutX = FALSE;
  dcb.fInX = FALSE;
  dcb.fNull = FALSE;
  dcb.fAbortOnError = FALSE;
  read_timeout_ms_ = 0;
  if (!SetCommState(port, &dcb) || !set_timeouts(port, read_timeout_ms_)) {
    const DWORD error = GetLastError();
    CloseHandle(port);
    return fail(FRUSTA_ERROR_IO, "%s: cannot set raw %d baud: %s", name_.c_str(), baud_,
                describe_error(error).c_str());
  }
  handle_ = port;
  return FRUSTA_OK;
}

void SerialStream::close() {
  if (handle_ != nullptr) CloseHandle(static_cast<HANDLE>(handle_));
  handle_ = nullptr;
}

IoStatus SerialStream::read(uint8_t* buffer, size_t capacity, int64_t timeout_us,
                            size_t* received) {
  *received = 0;
  if (handle_ == nullptr) return IoStatus::kDisconnected;
  HANDLE port = static_cast<HANDLE>(handle_);
  // the comm timeouts count whole milliseconds: round up, so a short wait still waits
  const uint32_t timeout_ms = static_cast<uint32_t>((timeout_us + 999) / 1000);
  if (timeout_ms != read_timeout_ms_) {
    if (!set_timeouts(port, timeout_ms)) return IoStatus::kDisconnected;
    read_timeout_ms_ = timeout_ms;
  }
  DWORD count = 0;
  const DWORD wanted = static_cast<DWORD>(capacity > MAXDWORD ? MAXDWORD : capacity);
  // a failed read is a port that is gone (unplugged: access denied or a device error)
  if (!ReadFile(port, buffer, wanted, &count, nullptr)) return IoStatus::kDisconnected;
  *received = count;
  return IoStatus::kOk;
}

IoStatus SerialStream::write(const uint8_t* data, size_t size, bool* dropped) {
  *dropped = false;
  if (handle_ == nullptr) return IoStatus::kDisconnected;
  DWORD written = 0;
  if (!WriteFile(static_cast<HANDLE>(handle_), data, static_cast<DWORD>(size), &written,
                 nullptr)) {
    if (GetLastError() != ERROR_TIMEOUT) return IoStatus::kDisconnected;
    written = 0;
  }
  // the glove is not draining its input: as on POSIX, the next full command resynchronises it
  if (written != size) *dropped = true;
  return IoStatus::kOk;
}

}  // namespace frusta
