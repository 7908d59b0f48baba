// SPDX-License-Identifier: MIT
// The only files the glTF loader reads: the input, and the buffers it names that are
// regular files inside the input's folder (symlinks resolved), all within a byte
// budget. FIFOs, devices, sockets and folders are refused without blocking.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <vector>

namespace frusta {

// A regular file of at most `limit` bytes, whole, into *out; false with the reason in
// *why otherwise. follow_symlinks false refuses a symlink as the last path component.
bool read_regular_file(const std::string& path, size_t limit, bool follow_symlinks,
                       std::vector<unsigned char>* out, std::string* why);

// What tinygltf may read besides the input: regular files inside `folder`. It looks a
// buffer up as base_dir/uri and then ./uri; only the first can pass.
struct Sandbox {
  std::string folder;  // canonical, no trailing slash (unless it is "/")
  size_t budget = 0;   // bytes still allowed

  bool under(const std::string& path) const;
};

// tinygltf's file callbacks confined to *sandbox (which must outlive the loader):
// no path expansion, reads inside the folder within the budget, no writes.
tinygltf::FsCallbacks sandboxed_files(Sandbox* sandbox);

}  // namespace frusta
