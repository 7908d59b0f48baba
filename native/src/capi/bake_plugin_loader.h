// SPDX-License-Identifier: MIT
// Finds and loads the baker library (bake/bake_plugin.h) once per process: the path
// in FRUSTA_BAKE_PLUGIN if set, else the file beside the module holding this code
// (the runtime library, or a test program), else the system's search path.
#pragma once

#include <string>

#include "bake/bake_plugin.h"

namespace frusta {

struct BakePlugin {
  decltype(&frusta_bake_plugin_bake) bake = nullptr;
  decltype(&frusta_bake_plugin_free) free = nullptr;
};

// The loaded baker, or null with *why saying what was tried and what failed.
const BakePlugin* bake_plugin(std::string* why);

}  // namespace frusta
