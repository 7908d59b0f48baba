// SPDX-License-Identifier: MIT
#include "glb_container.h"

#include <algorithm>
#include <cstdint>

namespace frusta {

namespace {

uint32_t le32(const unsigned char* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
         static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

void put_le32(std::vector<unsigned char>* out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<unsigned char>(v >> (8 * k)));
}

}  // namespace

bool split_glb(const std::vector<unsigned char>& b, GlbParts* out, std::string* why) {
  if (b.size() < 20) {
    *why = "a GLB shorter than its 20-byte header";
    return false;
  }
  const uint64_t length = le32(&b[8]);
  if (le32(&b[4]) != 2) {
    *why = "GLB version " + std::to_string(le32(&b[4])) + ", not 2";
    return false;
  }
  if (length > b.size()) {
    *why = "the GLB header says " + std::to_string(length) + " bytes, the file has " +
           std::to_string(b.size());
    return false;
  }
  const uint64_t json_size = le32(&b[12]);
  if (le32(&b[16]) != 0x4E4F534Au || 20 + json_size > length) {
    *why = "the GLB's first chunk is not JSON within the file";
    return false;
  }
  out->json = &b[20];
  out->json_size = static_cast<size_t>(json_size);
  const uint64_t next = 20 + json_size;
  if (next + 8 <= length && le32(&b[next + 4]) == 0x004E4942u) {  // "BIN\0"
    const uint64_t bin_size = le32(&b[next]);
    if (next + 8 + bin_size > length) {
      *why = "the GLB's BIN chunk of " + std::to_string(bin_size) + " bytes runs past its end";
      return false;
    }
    out->bin = &b[next + 8];
    out->bin_size = static_cast<size_t>(bin_size);
  }
  return true;
}

std::vector<unsigned char> make_glb(const std::string& json, const GlbParts& parts) {
  const size_t json_padded = (json.size() + 3) / 4 * 4;
  const size_t bin_padded = parts.bin ? std::max<size_t>(4, (parts.bin_size + 3) / 4 * 4) : 0;
  const size_t total = 20 + json_padded + (parts.bin ? 8 + bin_padded : 0);
  std::vector<unsigned char> glb;
  glb.reserve(total);
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  put_le32(&glb, 2);
  put_le32(&glb, static_cast<uint32_t>(total));
  put_le32(&glb, static_cast<uint32_t>(json_padded));
  put_le32(&glb, 0x4E4F534Au);
  glb.insert(glb.end(), json.begin(), json.end());
  glb.resize(20 + json_padded, ' ');
  if (parts.bin) {
    put_le32(&glb, static_cast<uint32_t>(bin_padded));
    put_le32(&glb, 0x004E4942u);
    glb.insert(glb.end(), parts.bin, parts.bin + parts.bin_size);
    glb.resize(total, 0);
  }
  return glb;
}

}  // namespace frusta
