// SPDX-License-Identifier: MIT
// Reading a whole input file that may come from anyone: a regular file only (opening
// a FIFO waits for a writer for ever, and a device or a directory has no size to bound
// the read by), no larger than the limit its format sets, read in one allocation of
// its own size.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/base.h"

namespace frusta {

// The bytes of the file at path in *out. Refused with FRUSTA_ERROR_IO (missing, not a
// regular file, unreadable) or FRUSTA_ERROR_CORRUPT_FILE (over max_bytes: "N bytes,
// more than <limit>"), the message starting with the path.
frusta_result read_file(const std::string& path, size_t max_bytes, const char* limit,
                        std::vector<uint8_t>* out);

}  // namespace frusta
