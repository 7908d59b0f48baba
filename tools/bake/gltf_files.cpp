// SPDX-License-Identifier: MIT
#include "gltf_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace frusta {

bool Sandbox::under(const std::string& path) const {
  const std::string prefix = folder == "/" ? folder : folder + "/";
  return path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0;
}

// O_NONBLOCK: opening a FIFO nobody writes to returns at once (then fstat refuses it)
// instead of waiting forever.
bool read_regular_file(const std::string& path, size_t limit, bool follow_symlinks,
                       std::vector<unsigned char>* out, std::string* why) {
  const int flags =
      O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY | (follow_symlinks ? 0 : O_NOFOLLOW);
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) {
    *why = std::strerror(errno);
    return false;
  }
  struct stat st {};
  bool ok = false;
  if (::fstat(fd, &st) != 0) {
    *why = std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    *why = "not a regular file (a FIFO, device, socket or folder could block or never end)";
  } else if (static_cast<uint64_t>(st.st_size) > limit) {
    *why = std::to_string(st.st_size) + " bytes, more than the " + std::to_string(limit) +
           " bytes the loader reads";
  } else {
    out->clear();
    out->reserve(static_cast<size_t>(st.st_size));
    unsigned char chunk[1 << 16];
    ok = true;
    for (;;) {
      const ssize_t n = ::read(fd, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        *why = std::strerror(errno);
        ok = false;
        break;
      }
      if (n == 0) break;
      if (static_cast<size_t>(n) > limit - out->size()) {  // it grew while being read
        *why = "more than the " + std::to_string(limit) + " bytes the loader reads";
        ok = false;
        break;
      }
      out->insert(out->end(), chunk, chunk + n);
    }
  }
  ::close(fd);
  return ok;
}

namespace {

std::string same_path(const std::string& path, void*) { return path; }  // no ~ or $VAR

bool exists_in_folder(const std::string& path, void* user) {
  const Sandbox& box = *static_cast<const Sandbox*>(user);
  struct stat st {};
  return box.under(path) && ::stat(path.c_str(), &st) == 0;  // what it is: read_in_folder says
}

bool read_in_folder(std::vector<unsigned char>* out, std::string* why, const std::string& path,
                    void* user) {
  Sandbox& box = *static_cast<Sandbox*>(user);
  if (!box.under(path)) {
    *why = "not inside the input's folder " + box.folder;
    return false;
  }
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) {
    *why = std::strerror(errno);
    return false;
  }
  if (!box.under(resolved)) {
    *why = std::string("it resolves to ") + resolved + ", outside the input's folder " + box.folder;
    return false;
  }
  if (!read_regular_file(resolved, box.budget, false, out, why)) return false;
  box.budget -= out->size();
  return true;
}

bool write_nothing(std::string* why, const std::string&, const std::vector<unsigned char>&, void*) {
  *why = "the loader writes no files";
  return false;
}

}  // namespace

tinygltf::FsCallbacks sandboxed_files(Sandbox* sandbox) {
  return {&exists_in_folder, &same_path, &read_in_folder, &write_nothing, sandbox};
}

}  // namespace frusta
