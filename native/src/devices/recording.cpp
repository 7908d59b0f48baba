// SPDX-License-Identifier: MIT
#include "devices/recording.h"

#include <fcntl.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <thread>

#include "core/error.h"
#include "core/periodic_clock.h"

namespace frusta {

namespace {

constexpr char kMagic[] = "frusta-recording 1 ";
constexpr size_t kMagicSize = sizeof kMagic - 1;
constexpr size_t kMaxProtocolName = 32;
constexpr size_t kMaxHeader = kMagicSize + kMaxProtocolName + 1;
constexpr size_t kRecordHead = 12;

void put_le(uint64_t value, int bytes, uint8_t* out) {
  for (int i = 0; i < bytes; ++i) out[i] = static_cast<uint8_t>(value >> (8 * i));
}
uint64_t get_le(const uint8_t* in, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<uint64_t>(in[i]) << (8 * i);
  return value;
}

#ifdef _WIN32
using FileStat = struct _stat64;
int stat_fd(int fd, FileStat* st) { return _fstat64(fd, st); }
int stat_path(const std::string& path, FileStat* st) { return _stat64(path.c_str(), st); }
bool is_regular(const FileStat& st) { return (st.st_mode & _S_IFMT) == _S_IFREG; }
const char* kind_of(const FileStat& st) {
  switch (st.st_mode & _S_IFMT) {
    case _S_IFDIR: return "a directory";
    case _S_IFCHR: return "a device";
    case _S_IFIFO: return "a pipe";
    default: return "not a file";
  }
}
int open_for_reading(const std::string& path) { return _open(path.c_str(), _O_RDONLY | _O_BINARY); }
int open_for_writing(const std::string& path) {
  return _open(path.c_str(), _O_WRONLY | _O_CREAT | _O_BINARY, _S_IREAD | _S_IWRITE);
}
bool empty_file(int fd) { return _chsize(fd, 0) == 0; }
long read_fd(int fd, uint8_t* buffer, size_t size) {
  return _read(fd, buffer, static_cast<unsigned>(std::min<size_t>(size, 1u << 30)));
}
void close_fd(int fd) { _close(fd); }
std::FILE* stream_of(int fd) { return _fdopen(fd, "wb"); }
#else
using FileStat = struct stat;
int stat_fd(int fd, FileStat* st) { return fstat(fd, st); }
int stat_path(const std::string& path, FileStat* st) { return stat(path.c_str(), st); }
bool is_regular(const FileStat& st) { return S_ISREG(st.st_mode); }
const char* kind_of(const FileStat& st) {
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}
// O_NONBLOCK: opening a FIFO must not wait for its other end (it is refused next)
int open_for_reading(const std::string& path) {
  return ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
}
int open_for_writing(const std::string& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_NONBLOCK | O_NOCTTY | O_CLOEXEC, 0666);
}
bool empty_file(int fd) { return ftruncate(fd, 0) == 0; }
long read_fd(int fd, uint8_t* buffer, size_t size) {
  ssize_t n;
  do n = ::read(fd, buffer, size);
  while (n < 0 && errno == EINTR);
  return static_cast<long>(n);
}
void close_fd(int fd) { ::close(fd); }
std::FILE* stream_of(int fd) { return fdopen(fd, "wb"); }
#endif

frusta_result not_a_file(const char* what, const std::string& path, const FileStat& st) {
  return fail(FRUSTA_ERROR_IO,
              "%s %s is %s, not a regular file: refused (it could block or never end)", what,
              path.c_str(), kind_of(st));
}

// Up to `limit` bytes of the regular file at `path` (from its start) into *bytes;
// *more: the file goes on past them (then, if `whole`, nothing is read).
frusta_result read_regular_file(const std::string& path, size_t limit, bool whole,
                                std::vector<uint8_t>* bytes, bool* more) {
  const int fd = open_for_reading(path);
  if (fd < 0)
    return fail(FRUSTA_ERROR_IO, "cannot open recording %s: %s", path.c_str(), std::strerror(errno));
  FileStat st{};
  if (stat_fd(fd, &st) != 0) {
    const int error = errno;
    close_fd(fd);
    return fail(FRUSTA_ERROR_IO, "cannot read recording %s: %s", path.c_str(), std::strerror(error));
  }
  if (!is_regular(st)) {
    close_fd(fd);
    return not_a_file("recording", path, st);
  }
  const size_t size = static_cast<size_t>(std::max<int64_t>(st.st_size, 0));
  if (whole && size > limit) {
    close_fd(fd);
    *more = true;
    return FRUSTA_OK;
  }
  // the size is a hint only: the file may change while it is read, and some (in /proc)
  // say 0 and have bytes
  bytes->assign(std::min(limit, size) + 1, 0);
  size_t have = 0;
  for (;;) {
    if (have == bytes->size()) {
      if (have > limit) break;
      bytes->resize(std::min(limit + 1, 2 * have));
    }
    const long n = read_fd(fd, bytes->data() + have, bytes->size() - have);
    if (n < 0) {
      const int error = errno;
      close_fd(fd);
      return fail(FRUSTA_ERROR_IO, "cannot read recording %s: %s", path.c_str(), std::strerror(error));
    }
    if (n == 0) break;
    have += static_cast<size_t>(n);
  }
  close_fd(fd);
  *more = have > limit;
  bytes->resize(std::min(have, limit));
  return FRUSTA_OK;
}

// The header line's protocol name, or an error naming the file.
frusta_result parse_header(const std::string& path, const std::vector<uint8_t>& bytes,
                           std::string* protocol, size_t* body) {
  const auto end = bytes.begin() + static_cast<ptrdiff_t>(std::min(bytes.size(), kMaxHeader));
  const auto newline = std::find(bytes.begin(), end, '\n');
  if (newline == end || static_cast<size_t>(newline - bytes.begin()) <= kMagicSize ||
      std::memcmp(bytes.data(), kMagic, kMagicSize) != 0)
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s is not a Frusta glove recording (no \"%s\" header)",
                path.c_str(), "frusta-recording 1 <protocol>");
  const std::string name(bytes.begin() + static_cast<ptrdiff_t>(kMagicSize), newline);
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
      return fail(FRUSTA_ERROR_FILE_FORMAT,
                  "recording %s: its header names no protocol (expected opengloves or frusta)",
                  path.c_str());
  *protocol = name;
  *body = static_cast<size_t>(newline - bytes.begin()) + 1;
  return FRUSTA_OK;
}

}  // namespace

Recorder::~Recorder() {
  if (file_ != nullptr) std::fclose(file_);
}

frusta_result Recorder::open(const std::string& path, const std::string& protocol,
                             int64_t max_bytes) {
  // asked first for the message's sake; the open file is checked again below
  FileStat st{};
  if (stat_path(path, &st) == 0 && !is_regular(st)) return not_a_file("recording", path, st);
  const int fd = open_for_writing(path);
  if (fd < 0)
    return fail(FRUSTA_ERROR_IO, "cannot create recording %s: %s", path.c_str(), std::strerror(errno));
  if (stat_fd(fd, &st) != 0 || !is_regular(st)) {
    close_fd(fd);
    return not_a_file("recording", path, st);
  }
  if (!empty_file(fd)) {
    const int error = errno;
    close_fd(fd);
    return fail(FRUSTA_ERROR_IO, "cannot empty recording %s: %s", path.c_str(), std::strerror(error));
  }
  file_ = stream_of(fd);
  if (file_ == nullptr) {
    close_fd(fd);
    return fail(FRUSTA_ERROR_IO, "cannot write recording %s", path.c_str());
  }
  const std::string header = kMagic + protocol + "\n";
  max_bytes_ = max_bytes;
  if (static_cast<int64_t>(header.size()) > max_bytes_ ||
      std::fwrite(header.data(), 1, header.size(), file_) != header.size())
    return fail(FRUSTA_ERROR_IO, "cannot write recording %s", path.c_str());
  written_ = static_cast<int64_t>(header.size());
  return FRUSTA_OK;
}

void Recorder::write(int64_t time_ns, const uint8_t* data, size_t size) {
  if (file_ == nullptr || failed_) return;
  while (size > 0) {
    const size_t chunk = std::min<size_t>(size, kMaxRecordBytes);
    if (written_ + static_cast<int64_t>(kRecordHead + chunk) > max_bytes_) {
      failed_ = true;  // full: what is there replays
      return;
    }
    uint8_t head[kRecordHead];
    put_le(static_cast<uint64_t>(time_ns), 8, head);
    put_le(chunk, 4, head + 8);
    if (std::fwrite(head, 1, sizeof head, file_) != sizeof head ||
        std::fwrite(data, 1, chunk, file_) != chunk) {
      failed_ = true;
      return;
    }
    written_ += static_cast<int64_t>(kRecordHead + chunk);
    data += chunk;
    size -= chunk;
  }
}

frusta_result read_recording_protocol(const std::string& path, std::string* protocol) {
  std::vector<uint8_t> bytes;
  bool more = false;
  if (frusta_result r = read_regular_file(path, kMaxHeader, false, &bytes, &more)) return r;
  size_t body = 0;
  return parse_header(path, bytes, protocol, &body);
}

ReplayStream::ReplayStream(std::string path, bool real_time, bool loop)
    : path_(std::move(path)), real_time_(real_time), loop_(loop), name_("replay " + path_) {}

frusta_result ReplayStream::load(std::string* protocol) {
  if (!loaded_) {
    std::vector<uint8_t> file;
    bool more = false;
    if (frusta_result r = read_regular_file(path_, static_cast<size_t>(kMaxRecordingBytes), true, &file, &more))
      return r;
    if (more)
      return fail(FRUSTA_ERROR_FILE_FORMAT, "recording %s is larger than the %lld bytes a recording may be",
                  path_.c_str(), static_cast<long long>(kMaxRecordingBytes));
    std::string name;
    size_t at = 0;
    if (frusta_result r = parse_header(path_, file, &name, &at)) return r;
    std::vector<Record> records;
    int64_t previous_ns = 0;
    // a record whose head or bytes are cut off at the end is played up to where it ends
    while (at + kRecordHead <= file.size()) {
      const int64_t time_ns = static_cast<int64_t>(get_le(&file[at], 8));
      const uint64_t claimed = get_le(&file[at + 8], 4);
      if (claimed == 0 || claimed > kMaxRecordBytes || time_ns < previous_ns)
        return fail(FRUSTA_ERROR_CORRUPT_FILE,
                    "recording %s: the record at byte %zu is corrupt (%llu bytes at %lld ns, "
                    "after %lld ns)",
                    path_.c_str(), at, static_cast<unsigned long long>(claimed),
                    static_cast<long long>(time_ns), static_cast<long long>(previous_ns));
      const size_t size = std::min<size_t>(claimed, file.size() - at - kRecordHead);
      records.push_back(Record{time_ns, at + kRecordHead, size});
      previous_ns = time_ns;
      at += kRecordHead + size;
    }
    bytes_ = std::move(file);
    records_ = std::move(records);
    protocol_ = std::move(name);
    loaded_ = true;
  }
  if (protocol != nullptr) *protocol = protocol_;
  return FRUSTA_OK;
}

frusta_result ReplayStream::open() {
  if (frusta_result r = load()) return r;
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
