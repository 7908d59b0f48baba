// SPDX-License-Identifier: MIT
// libFuzzer target: the glTF loader exactly as frusta-bake runs it (load by path,
// then check_mesh), on any bytes. No crash, sanitizer report, hang (-timeout) or
// blow-up (-rss_limit_mb) is allowed, and nothing may be opened outside the
// input's folder: every open during a load is checked against it.
//
// Each input is written into a private folder, as model.glb when it starts with
// the GLB magic and model.gltf otherwise. The folder is laid out as the loader
// tests' hostile corpus (tests/tools/bake/corpus, also a seed folder) expects:
// in/ holds the buffers seeds name (triangle.bin, sub/cube.bin, tetra.bin), a
// symlink inside (alias.bin), symlinks out (link.bin to ../outside.bin, zero.bin
// to /dev/zero), a FIFO (fifo.bin) and a file over the size limit (huge.bin,
// sparse). Outside in/ lie copies of the buffers, so that "../" put in front of a
// seed's URI names a file that exists. gltf.dict names them all.
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bake/triangle_mesh.h"
#include "gltf_loader.h"

namespace {

std::string g_root;    // private, canonical; holds outside.bin
std::string g_folder;  // g_root + "/in": the input's folder
bool g_watching = false;

// an open for reading that succeeded while the loader ran: where did it land? (Opens
// for writing are libFuzzer's own, saving the input after a crash in the loader.)
void check_opened(int fd, const char* asked, int flags) {
  if (!g_watching || fd < 0 || (flags & O_ACCMODE) != O_RDONLY) return;
  char link[64], target[4096];
  std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, target, sizeof target - 1);
  if (n <= 0) return;
  target[n] = '\0';
  const size_t k = g_folder.size();
  if (std::strncmp(target, g_folder.c_str(), k) == 0 && (target[k] == '\0' || target[k] == '/'))
    return;
  std::fprintf(stderr,
               "==gltf_loader_fuzz== the loader opened %s (as \"%s\"), outside the input's "
               "folder %s\n",
               target, asked, g_folder.c_str());
  g_watching = false;
  std::abort();
}

// an open about to block: opening a FIFO for reading waits for a writer that never
// comes (libFuzzer's alarm interrupts the wait, so without this it is only slow)
void check_blocking(int dir, const char* path, int flags) {
  struct stat st {};
  if (!g_watching || (flags & O_NONBLOCK) || (flags & O_ACCMODE) != O_RDONLY ||
      fstatat(dir, path, &st, 0) != 0 || !S_ISFIFO(st.st_mode))
    return;
  std::fprintf(stderr,
               "==gltf_loader_fuzz== the loader opens the FIFO \"%s\" blocking: it "
               "hangs until something writes to it\n",
               path);
  g_watching = false;
  std::abort();
}

template <class F>
F real(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

void write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

template <class T>
void append(std::vector<uint8_t>& out, const std::vector<T>& values) {
  const auto* p = reinterpret_cast<const uint8_t*>(values.data());
  out.insert(out.end(), p, p + values.size() * sizeof(T));
}

// triangle.bin: 3 float VEC3 at 0, 3 uint16 indices at 36 (44 bytes with padding).
// cube.bin: 8 float VEC3 at 0, 36 uint16 indices at 96 (168 bytes).
// tetra.bin: 4 float VEC3 at 0, 12 uint16 indices at 48 (72 bytes), as the corpus's.
std::vector<uint8_t> triangle_bin() {
  std::vector<uint8_t> b;
  append(b, std::vector<float>{0, 0, 0, 0.1f, 0, 0, 0, 0.1f, 0});
  append(b, std::vector<uint16_t>{0, 1, 2, 0});
  return b;
}

std::vector<uint8_t> cube_bin() {
  std::vector<float> v;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) v.push_back((i >> k & 1) ? 0.05f : -0.05f);
  std::vector<uint8_t> b;
  append(b, v);
  append(b, std::vector<uint16_t>{0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5});
  return b;
}

std::vector<uint8_t> tetra_bin() {
  std::vector<uint8_t> b;
  append(b, std::vector<float>{0, 0, 0, 0.05f, 0, 0, 0, 0.05f, 0, 0, 0, 0.05f});
  append(b, std::vector<uint16_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
  return b;
}

void remove_root() {
  std::error_code ignored;
  std::filesystem::remove_all(g_root, ignored);
}

// A run that crashed never removed its folder: remove those whose process is gone.
void remove_stale_folders(const std::filesystem::path& temp) {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const fs::directory_entry& e : fs::directory_iterator(temp, error)) {
    const std::string name = e.path().filename().string();
    const std::string prefix = "frusta-gltf-fuzz.";
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      fs::remove_all(e.path(), error);
  }
}

void make_folder() {
  namespace fs = std::filesystem;
  remove_stale_folders(fs::temp_directory_path());
  std::string pattern = fs::temp_directory_path().string() + "/frusta-gltf-fuzz." +
                        std::to_string(getpid()) + ".XXXXXX";
  if (!mkdtemp(pattern.data())) std::abort();
  g_root = fs::canonical(pattern).string();
  g_folder = g_root + "/in";
  for (const std::string& dir : {g_root, g_folder}) {
    fs::create_directories(dir + "/sub");
    write_file(dir + "/triangle.bin", triangle_bin());
    write_file(dir + "/sub/cube.bin", cube_bin());
    write_file(dir + "/tetra.bin", tetra_bin());
  }
  write_file(g_root + "/outside.bin", tetra_bin());
  write_file(g_root + "/outside.png", {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
  fs::create_symlink("tetra.bin", g_folder + "/alias.bin");
  fs::create_symlink("../outside.bin", g_folder + "/link.bin");
  fs::create_symlink("/dev/zero", g_folder + "/zero.bin");
  if (mkfifo((g_folder + "/fifo.bin").c_str(), 0600) != 0) std::abort();
  write_file(g_folder + "/huge.bin", {});
  fs::resize_file(g_folder + "/huge.bin", frusta::GltfLimits::kMaxFileBytes + 1);
  std::atexit(remove_root);
}

// what matters here of an fopen mode: reading only, or not
int fopen_flags(const char* mode) {
  return mode[0] == 'r' && !std::strchr(mode, '+') ? O_RDONLY : O_RDWR;
}

// open's mode argument is there only when the flags create a file
mode_t open_mode(int flags, va_list args) {
  return (flags & (O_CREAT | O_TMPFILE)) ? static_cast<mode_t>(va_arg(args, unsigned int)) : 0;
}

}  // namespace

// The opens the loader can reach (tinygltf: fopen and std::ifstream, which opens with
// fopen64; open and openat), checked while g_watching. They replace ASan's
// interceptors, which are weak.
extern "C" FILE* fopen(const char* path, const char* mode) {
  static const auto next = real<FILE* (*)(const char*, const char*)>("fopen");
  const int flags = fopen_flags(mode);
  check_blocking(AT_FDCWD, path, flags);
  FILE* f = next(path, mode);
  if (f) check_opened(fileno(f), path, flags);
  return f;
}

extern "C" FILE* fopen64(const char* path, const char* mode) {
  static const auto next = real<FILE* (*)(const char*, const char*)>("fopen64");
  const int flags = fopen_flags(mode);
  check_blocking(AT_FDCWD, path, flags);
  FILE* f = next(path, mode);
  if (f) check_opened(fileno(f), path, flags);
  return f;
}

extern "C" int open(const char* path, int flags, ...) {
  static const auto next = real<int (*)(const char*, int, ...)>("open");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  check_blocking(AT_FDCWD, path, flags);
  const int fd = next(path, flags, mode);
  check_opened(fd, path, flags);
  return fd;
}

extern "C" int open64(const char* path, int flags, ...) {
  static const auto next = real<int (*)(const char*, int, ...)>("open64");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  check_blocking(AT_FDCWD, path, flags);
  const int fd = next(path, flags, mode);
  check_opened(fd, path, flags);
  return fd;
}

extern "C" int openat(int dir, const char* path, int flags, ...) {
  static const auto next = real<int (*)(int, const char*, int, ...)>("openat");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  check_blocking(dir, path, flags);
  const int fd = next(dir, path, flags, mode);
  check_opened(fd, path, flags);
  return fd;
}

extern "C" int openat64(int dir, const char* path, int flags, ...) {
  static const auto next = real<int (*)(int, const char*, int, ...)>("openat64");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  check_blocking(dir, path, flags);
  const int fd = next(dir, path, flags, mode);
  check_opened(fd, path, flags);
  return fd;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  make_folder();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string path = g_folder + (binary ? "/model.glb" : "/model.gltf");
  write_file(path, std::vector<uint8_t>(data, data + size));

  g_watching = true;
  frusta::GltfLoadResult input;
  const frusta_result loaded = frusta::load_gltf_triangles(path, &input);
  g_watching = false;
  if (loaded != FRUSTA_OK) return 0;
  // what the loader returns indexes its own vertices (check_mesh would only report it)
  for (const auto& t : input.mesh.triangles)
    for (uint32_t i : t)
      if (i >= input.mesh.vertices.size()) std::abort();
  frusta::check_mesh(input.mesh, path.c_str());
  return 0;
}
