// SPDX-License-Identifier: MIT
// libFuzzer target: the glTF loader exactly as frusta-bake runs it (load by path,
// then check_mesh), on any bytes. No crash, sanitizer report, hang (-timeout) or
// blow-up (-rss_limit_mb) is allowed, and nothing may be opened outside the
// input's folder: every open during a load is checked against it.
//
// Each input is written into a private folder, as model.glb when it starts with
// the GLB magic and model.gltf otherwise. Beside it are the buffers the hand-made
// seeds name (triangle.bin, sub/cube.bin) and what a hostile file would reach
// for: a FIFO (fifo.bin), a symlink (link.bin) to a buffer outside the folder
// (../outside.bin). gltf.dict names them all.
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

// an open that succeeded while the loader ran: where did it land?
void check_opened(int fd, const char* asked) {
  if (!g_watching || fd < 0) return;
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

void remove_root() {
  std::error_code ignored;
  std::filesystem::remove_all(g_root, ignored);
}

void make_folder() {
  std::string pattern =
      std::filesystem::temp_directory_path().string() + "/frusta-gltf-fuzz.XXXXXX";
  if (!mkdtemp(pattern.data())) std::abort();
  g_root = std::filesystem::canonical(pattern).string();
  g_folder = g_root + "/in";
  std::filesystem::create_directories(g_folder + "/sub");
  write_file(g_folder + "/triangle.bin", triangle_bin());
  write_file(g_folder + "/sub/cube.bin", cube_bin());
  write_file(g_root + "/outside.bin", triangle_bin());
  std::filesystem::create_symlink("../outside.bin", g_folder + "/link.bin");
  if (mkfifo((g_folder + "/fifo.bin").c_str(), 0600) != 0) std::abort();
  std::atexit(remove_root);
}

// open's mode argument is there only when the flags create a file
mode_t open_mode(int flags, va_list args) {
  return (flags & (O_CREAT | O_TMPFILE)) ? static_cast<mode_t>(va_arg(args, unsigned int)) : 0;
}

}  // namespace

// The opens the loader can reach (tinygltf: fopen and std::ifstream, which opens with
// fopen64), wrapped while g_watching. These replace ASan's interceptors, which are weak.
extern "C" FILE* fopen(const char* path, const char* mode) {
  static const auto next = real<FILE* (*)(const char*, const char*)>("fopen");
  FILE* f = next(path, mode);
  if (f) check_opened(fileno(f), path);
  return f;
}

extern "C" FILE* fopen64(const char* path, const char* mode) {
  static const auto next = real<FILE* (*)(const char*, const char*)>("fopen64");
  FILE* f = next(path, mode);
  if (f) check_opened(fileno(f), path);
  return f;
}

extern "C" int open(const char* path, int flags, ...) {
  static const auto next = real<int (*)(const char*, int, ...)>("open");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  const int fd = next(path, flags, mode);
  check_opened(fd, path);
  return fd;
}

extern "C" int open64(const char* path, int flags, ...) {
  static const auto next = real<int (*)(const char*, int, ...)>("open64");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  const int fd = next(path, flags, mode);
  check_opened(fd, path);
  return fd;
}

extern "C" int openat(int dir, const char* path, int flags, ...) {
  static const auto next = real<int (*)(int, const char*, int, ...)>("openat");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  const int fd = next(dir, path, flags, mode);
  check_opened(fd, path);
  return fd;
}

extern "C" int openat64(int dir, const char* path, int flags, ...) {
  static const auto next = real<int (*)(int, const char*, int, ...)>("openat64");
  va_list args;
  va_start(args, flags);
  const mode_t mode = open_mode(flags, args);
  va_end(args);
  const int fd = next(dir, path, flags, mode);
  check_opened(fd, path);
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
