// SPDX-License-Identifier: MIT
// A glove's input stream on file, to replay it for tests, the demo and bug reports.
// The bytes are kept as the glove sent them, so a replay goes through the same
// protocol decoder, calibration and checks as the live glove did. Format:
//   "frusta-recording 1 <protocol>\n"   protocol: opengloves | frusta
//   records until the end: int64 time since the recording began (ns), uint32 byte
//   count (<= 65536), the bytes; integers little-endian
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "devices/byte_stream.h"

namespace frusta {

constexpr uint32_t kMaxRecordBytes = 65536;

// Written by the device thread: fwrite into the C library's buffer, so a record costs a
// copy, not a system call.
class Recorder {
 public:
  ~Recorder();
  frusta_result open(const std::string& path, const std::string& protocol);
  void write(int64_t time_ns, const uint8_t* data, size_t size);
  bool failed() const { return failed_; }

 private:
  std::FILE* file_ = nullptr;
  bool failed_ = false;  // the disk refused a write: recording stops, the glove does not
};

// Reads a recording's header: its protocol name, in *protocol.
frusta_result read_recording_protocol(const std::string& path, std::string* protocol);

// A recording played back as a glove's byte stream: in real time (each record when its
// time comes, counted from open()) or as fast as the reader takes it. At the end the
// glove "disconnects"; with `loop`, opening again starts it over. Commands written to
// it are counted and dropped.
class ReplayStream final : public ByteStream {
 public:
  ReplayStream(std::string path, bool real_time, bool loop);
  frusta_result open() override;
  void close() override;
  bool is_open() const override { return open_; }
  IoStatus read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) override;
  IoStatus write(const uint8_t* data, size_t size, bool* dropped) override;
  const std::string& name() const override { return name_; }

  int64_t commands_written() const { return commands_; }

 private:
  struct Record {
    int64_t time_ns;
    size_t offset, size;  // in bytes_
  };
  std::string path_;
  bool real_time_, loop_;
  std::string name_;
  bool loaded_ = false, open_ = false, ended_ = false;
  std::vector<uint8_t> bytes_;
  std::vector<Record> records_;
  size_t next_ = 0, consumed_ = 0;  // record, and bytes of it already read
  int64_t start_ns_ = 0;
  int64_t commands_ = 0;
};

}  // namespace frusta
