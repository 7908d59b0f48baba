// SPDX-License-Identifier: MIT
#include "devices/recording.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

#include "core/error.h"
#include "runtime/periodic_clock.h"

namespace frusta {

namespace {

constexpr char kMagic[] = "frusta-recording 1 ";

void put_le(uint64_t value, int bytes, uint8_t* out) {
  for (int i = 0; i < bytes; ++i) out[i] = static_cast<uint8_t>(value >> (8 * i));
}
uint64_t get_le(const uint8_t* in, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<uint64_t>(in[i]) << (8 * i);
  return value;
}

// the header line, or an error naming the file
frusta_result parse_header(const std::string& path, const std::vector<uint8_t>& bytes,
                           std::string* protocol, size_t* body) {
  const auto newline = std::find(bytes.begin(), bytes.end(), '\n');
  const size_t magic = sizeof kMagic - 1;
  if (newline == bytes.end() || static_cast<size_t>(newline - bytes.begin()) <= magic ||
      std::memcmp(bytes.data(), kMagic, magic) != 0)
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s is not a Frusta glove recording (no \"%s\" header)",
                path.c_str(), "frusta-recording 1 <protocol>");
  *protocol = std::string(bytes.begin() + static_cast<ptrdiff_t>(magic), newline);
  *body = static_cast<size_t>(newline - bytes.begin()) + 1;
  return FRUSTA_OK;
}

frusta_result read_all(const std::string& path, std::vector<uint8_t>* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(FRUSTA_ERROR_IO, "cannot open recording %s: %s", path.c_str(), std::strerror(errno));
  bytes->assign(std::istreambuf_iterator<char>(in), {});
  return FRUSTA_OK;
}

}  // namespace

Recorder::~Recorder() {
  if (file_ != nullptr) std::fclose(file_);
}

frusta_result Recorder::open(const std::string& path, const std::string& protocol) {
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr)
    return fail(FRUSTA_ERROR_IO, "cannot create recording %s: %s", path.c_str(), std::strerror(errno));
  const std::string header = kMagic + protocol + "\n";
  if (std::fwrite(header.data(), 1, header.size(), file_) != header.size())
    return fail(FRUSTA_ERROR_IO, "cannot write recording %s", path.c_str());
  return FRUSTA_OK;
}

void Recorder::write(int64_t time_ns, const uint8_t* data, size_t size) {
  if (file_ == nullptr || failed_) return;
  while (size > 0) {
    const size_t chunk = std::min<size_t>(size, kMaxRecordBytes);
    uint8_t head[12];
    put_le(static_cast<uint64_t>(time_ns), 8, head);
    put_le(chunk, 4, head + 8);
    if (std::fwrite(head, 1, sizeof head, file_) != sizeof head ||
        std::fwrite(data, 1, chunk, file_) != chunk) {
      failed_ = true;
      return;
    }
    data += chunk;
    size -= chunk;
  }
}

frusta_result read_recording_protocol(const std::string& path, std::string* protocol) {
  std::vector<uint8_t> bytes;
  if (frusta_result r = read_all(path, &bytes)) return r;
  size_t body = 0;
  return parse_header(path, bytes, protocol, &body);
}

ReplayStream::ReplayStream(std::string path, bool real_time, bool loop)
    : path_(std::move(path)), real_time_(real_time), loop_(loop), name_("replay " + path_) {}

frusta_result ReplayStream::open() {
  if (!loaded_) {
    std::vector<uint8_t> file;
    if (frusta_result r = read_all(path_, &file)) return r;
    std::string protocol;
    size_t at = 0;
    if (frusta_result r = parse_header(path_, file, &protocol, &at)) return r;
    // a cut-off last record (the recorder was killed) is played up to where it ends
    while (at + 12 <= file.size()) {
      const int64_t time_ns = static_cast<int64_t>(get_le(&file[at], 8));
      const size_t size = std::min<size_t>(get_le(&file[at + 8], 4), file.size() - at - 12);
      if (size > kMaxRecordBytes || time_ns < 0)
        return fail(FRUSTA_ERROR_CORRUPT_FILE, "recording %s: record at byte %zu is corrupt",
                    path_.c_str(), at);
      records_.push_back(Record{time_ns, bytes_.size(), size});
      bytes_.insert(bytes_.end(), file.begin() + static_cast<ptrdiff_t>(at + 12),
                    file.begin() + static_cast<ptrdiff_t>(at + 12 + size));
      at += 12 + size;
    }
    loaded_ = true;
  }
  if (ended_ && !loop_)
    return fail(FRUSTA_ERROR_WRONG_STATE, "%s: the recording has ended", name_.c_str());
  next_ = consumed_ = 0;
  ended_ = false;
  start_ns_ = steady_ns();
  open_ = true;
  return FRUSTA_OK;
}

void ReplayStream::close() { open_ = false; }

IoStatus ReplayStream::read(uint8_t* buffer, size_t capacity, int64_t timeout_us, size_t* received) {
  *received = 0;
  if (!open_) return IoStatus::kDisconnected;
  if (next_ >= records_.size()) {
    ended_ = true;
    return IoStatus::kDisconnected;
  }
  const Record& record = records_[next_];
  if (real_time_) {
    const int64_t due = start_ns_ + record.time_ns;
    const int64_t wait_ns = due - steady_ns();
    if (wait_ns > timeout_us * 1000) {
      std::this_thread::sleep_for(std::chrono::microseconds(timeout_us));
      return IoStatus::kOk;
    }
    if (wait_ns > 0) std::this_thread::sleep_for(std::chrono::nanoseconds(wait_ns));
  }
  const size_t n = std::min(capacity, record.size - consumed_);
  std::memcpy(buffer, bytes_.data() + record.offset + consumed_, n);
  consumed_ += n;
  if (consumed_ == record.size) {
    ++next_;
    consumed_ = 0;
  }
  *received = n;
  return IoStatus::kOk;
}

IoStatus ReplayStream::write(const uint8_t* /*data*/, size_t /*size*/, bool* dropped) {
  *dropped = false;
  ++commands_;
  return open_ ? IoStatus::kOk : IoStatus::kDisconnected;
}

}  // namespace frusta
