// SPDX-License-Identifier: MIT
// Every allocation through operator new in a test binary that links
// allocation_counter.cpp is counted, so a test can require none: the 1 kHz path
// allocates nothing.
#pragma once

#include <cstdint>

namespace frusta {

// Allocations so far, on every thread.
int64_t allocation_count();

}  // namespace frusta
