// SPDX-License-Identifier: MIT
// The loader's one way to refuse a file: FRUSTA_ERROR_FILE_FORMAT, the file's path,
// then what is wrong (printf-style).
#pragma once

#include <cstdio>
#include <string>

#include "core/error.h"

namespace frusta {

template <class... Args>
frusta_result gltf_format_error(const std::string& path, const char* format, Args... args) {
  char message[400];
  std::snprintf(message, sizeof message, format, args...);
  return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: %s", path.c_str(), message);
}

}  // namespace frusta
