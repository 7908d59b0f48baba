// SPDX-License-Identifier: MIT
// A glove's input stream on file, to replay it for tests, the demo and bug reports.
// The bytes are kept as the glove sent them, so a replay goes through the same
// protocol decoder, calibration and checks as the live glove did. Format:
//   "frusta-recording 1 <protocol>\n"   protocol: opengloves | frusta
//   records until the end: int64 time since the recording began (ns), uint32 byte
//   count (1 ... 65536), the bytes; integers little-endian; times never decrease
// A recording is a regular file of at most kMaxRecordingBytes. Anything else (a FIFO,
// a device such as /dev/zero, a directory) is refused before a byte is read or
// written: opening it could block for ever, reading it might never end.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "devices/byte_stream.h"

namespace frusta {

constexpr uint32_t kMaxRecordBytes = 65536;
// 1 GiB: over four hours of a 1 kHz binary-profile glove; a replay holds it in memory
constexpr int64_t kMaxRecordingBytes = int64_t{1} << 30;

// Written by the device thread: fwrite into the C library's buffer, so a record costs a
// copy, not a system call.
class Recorder {
 public:
  ~Recorder();
  // Creates `path`, or empties it if it is a regular file. The recording stops (and
  // failed() says so) once it would grow past max_bytes, so it can always be replayed.
  frusta_result open(const std::string& path, const std::string& protocol,
                     int64_t max_bytes = kMaxRecordingBytes);
  void write(int64_t time_ns, const uint8_t* data, size_t size);
  bool failed() const { return failed_; }

 private:
  std::FILE* file_ = nullptr;
  bool failed_ = false;  // the disk refused a write, or the size limit came: recording
                         // stops, the glove does not
  int64_t written_ = 0, max_bytes_ = kMaxRecordingBytes;
};

// Reads a recording's header (and nothing more): its protocol name, in *protocol.
frusta_result read_recording_protocol(const std::string& path, std::string* protocol);

// A recording played back as a glove's byte stream: in real time (each record when its
// time comes, counted from open()) or as fast as the reader takes it. At the end the
// glove "disconnects"; with `loop`, opening again starts it over. Commands written to
// it are counted and dropped.
class ReplayStream final : public ByteStream {
 public:
  ReplayStream(std::string path, bool real_time, bool loop);
  // Reads and checks the whole recording, once (open() does it if not done); the
  // protocol its header names goes to *protocol. A record cut off at the end (the
  // recorder was killed) is played as far as it goes; any other fault refuses it all.
  frusta_result load(std::string* protocol = nullptr);
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
  std::string protocol_;
  bool loaded_ = false, open_ = false, ended_ = false;
  std::vector<uint8_t> bytes_;  // the whole file
  std::vector<Record> records_;
  size_t next_ = 0, consumed_ = 0;  // record, and bytes of it already read
  int64_t start_ns_ = 0;
  int64_t commands_ = 0;
};

}  // namespace frusta
