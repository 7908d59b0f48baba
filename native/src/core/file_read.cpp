// SPDX-License-Identifier: MIT
#include "core/file_read.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.h"

namespace frusta {

frusta_result read_file(const std::string& path, size_t max_bytes, const char* limit,
                        std::vector<uint8_t>* out) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error)
    return fail(FRUSTA_ERROR_IO, "%s: cannot open it for reading (%s)", path.c_str(),
                error.message().c_str());
  if (!std::filesystem::is_regular_file(status))
    return fail(FRUSTA_ERROR_IO, "%s: not a regular file (a directory, a device or a pipe)",
                path.c_str());
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return fail(FRUSTA_ERROR_IO, "%s: cannot open it for reading", path.c_str());
  const std::streamoff size = in.tellg();
  if (size < 0 || static_cast<uint64_t>(size) > max_bytes)
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: %lld bytes, more than %s (%zu)", path.c_str(),
                static_cast<long long>(size), limit, max_bytes);
  out->resize(static_cast<size_t>(size));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(out->data()), size);
  if (!in) return fail(FRUSTA_ERROR_IO, "%s: read failed", path.c_str());
  return FRUSTA_OK;
}

}  // namespace frusta
