// SPDX-License-Identifier: MIT
// The hostile glTF corpus (corpus/, written by corpus/make_corpus.py) laid out in a
// private temporary folder the way its files expect, and a watch that tells which
// files beside the input's folder anything opened. Shared by the loader's test and
// frusta-bake's.
#pragma once

#include <fcntl.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gltf_loader.h"

namespace frusta::corpus {

struct Case {
  std::string file;
  std::string result;    // a frusta_result's name
  std::string fragment;  // of the message
};

inline std::vector<unsigned char> tetra_bin() {
  // as make_corpus.py's TETRA: four float positions, twelve uint16 indices
  const float p[12] = {0, 0, 0, 0.05f, 0, 0, 0, 0.05f, 0, 0, 0, 0.05f};
  const uint16_t i[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::vector<unsigned char> b(sizeof p + sizeof i);
  std::memcpy(b.data(), p, sizeof p);
  std::memcpy(b.data() + sizeof p, i, sizeof i);
  return b;
}

inline void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// {"a": ... 0 ...} (or [[...0...]]) `depth` levels deep in the extras of a glTF whose
// mesh is the corpus's tetrahedron; as a .gltf or as a GLB's JSON chunk
inline std::string deep_gltf(int depth, bool arrays) {
  std::string open, close;
  for (int k = 0; k < depth; ++k) {
    open += arrays ? "[" : "{\"a\": ";
    close += arrays ? "]" : "}";
  }
  return R"({"asset": {"version": "2.0"}, "extras": )" + open + "0" + close + R"(,
 "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"byteLength": 72}],
 "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
               {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}]})";
}

inline std::string glb_of(std::string json, const std::vector<unsigned char>& bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string body = u32(static_cast<uint32_t>(json.size())) + "JSON" + json +
                           u32(static_cast<uint32_t>(bin.size())) + std::string("BIN\0", 4) +
                           std::string(bin.begin(), bin.end());
  return "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + body.size())) + body;
}

// root/outside.bin, root/outside.png: what nothing may open
// root/in/: the corpus, the buffers it names, and the deep files made here
class Folder {
 public:
  static constexpr int kDeep = 50000;

  Folder() {
    std::string pattern = std::filesystem::temp_directory_path().string() + "/frusta-corpus.XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    root_ = std::filesystem::canonical(pattern).string();
    in_ = root_ + "/in";
    std::filesystem::create_directories(in_ + "/sub");
    const std::vector<unsigned char> tetra = tetra_bin();
    const std::string tetra_bytes(tetra.begin(), tetra.end());
    write_file(root_ + "/outside.bin", tetra_bytes);
    write_file(root_ + "/outside.png", "\x89PNG\r\n\x1a\n");
    write_file(in_ + "/tetra.bin", tetra_bytes);
    std::filesystem::create_symlink("tetra.bin", in_ + "/alias.bin");
    std::filesystem::create_symlink("../outside.bin", in_ + "/link.bin");
    std::filesystem::create_symlink("/dev/zero", in_ + "/zero.bin");
    if (mkfifo((in_ + "/fifo.bin").c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
    // sparse: one byte over the limit costs no disk
    write_file(in_ + "/huge.bin", "");
    std::filesystem::resize_file(in_ + "/huge.bin", GltfLimits::kMaxFileBytes + 1);
    for (const Case& c : cases())
      std::filesystem::copy_file(std::string(FRUSTA_GLTF_CORPUS_DIR) + "/" + c.file,
                                 in_ + "/" + c.file);
    write_file(in_ + "/deep_extras_objects.gltf", deep_gltf(kDeep, false));
    write_file(in_ + "/deep_extras_arrays.gltf", deep_gltf(kDeep, true));
    write_file(in_ + "/deep_json_chunk.glb", glb_of(deep_gltf(kDeep, false), tetra));
  }
  ~Folder() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;

  const std::string& root() const { return root_; }
  std::string in(const std::string& name) const { return in_ + "/" + name; }

  // what corpus/cases.tsv lists, and the deep files made here
  static std::vector<Case> cases() {
    std::ifstream tsv(std::string(FRUSTA_GLTF_CORPUS_DIR) + "/cases.tsv");
    if (!tsv) throw std::runtime_error("no corpus/cases.tsv");
    std::vector<Case> out;
    std::string line;
    while (std::getline(tsv, line)) {
      if (line.empty() || line[0] == '#') continue;
      Case c;
      std::istringstream fields(line);
      std::getline(fields, c.file, '\t');
      std::getline(fields, c.result, '\t');
      std::getline(fields, c.fragment);
      out.push_back(c);
    }
    return out;
  }
  static std::vector<Case> all_cases() {
    std::vector<Case> out = cases();
    const char* deep = "JSON nested more than 64 levels deep (in \"extras\")";
    for (const char* f :
         {"deep_extras_objects.gltf", "deep_extras_arrays.gltf", "deep_json_chunk.glb"})
      out.push_back({f, "FRUSTA_ERROR_FILE_FORMAT", deep});
    return out;
  }

 private:
  std::string root_, in_;
};

// Every file opened or read directly in `folder` (not below it) from now on, by any
// process: the kernel queues the event before open() returns, so no waiting is needed.
class OpenWatch {
 public:
  explicit OpenWatch(const std::string& folder) {
    fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd_ < 0 || inotify_add_watch(fd_, folder.c_str(), IN_OPEN | IN_ACCESS) < 0)
      throw std::runtime_error("inotify failed");
  }
  ~OpenWatch() { close(fd_); }
  OpenWatch(const OpenWatch&) = delete;
  OpenWatch& operator=(const OpenWatch&) = delete;

  // the files (not folders) opened or read since the last call
  std::vector<std::string> take() {
    std::vector<std::string> names;
    alignas(inotify_event) char buffer[4096];
    for (;;) {
      const ssize_t n = read(fd_, buffer, sizeof buffer);
      if (n <= 0) break;
      for (ssize_t at = 0; at < n;) {
        const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
        if (!(e->mask & IN_ISDIR) && e->len > 0) names.emplace_back(e->name);
        at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      }
    }
    return names;
  }

 private:
  int fd_ = -1;
};

}  // namespace frusta::corpus
