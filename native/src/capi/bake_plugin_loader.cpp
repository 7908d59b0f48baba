// SPDX-License-Identifier: MIT
#include "capi/bake_plugin_loader.h"

#include <cstdlib>
#include <mutex>

#if defined(_WIN32)
#  include <windows.h>
#else
#  include <dlfcn.h>
#endif

namespace frusta {

namespace {

#if defined(_WIN32)
constexpr char kFileName[] = "frusta_bake.dll";

std::string beside_this_module() {
  HMODULE self = nullptr;
  char path[MAX_PATH];
  if (!GetModuleHandleExA(GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS |
                              GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
                          reinterpret_cast<LPCSTR>(&beside_this_module), &self) ||
      GetModuleFileNameA(self, path, sizeof path) == 0)
    return kFileName;
  const std::string module = path;
  return module.substr(0, module.find_last_of("\\/") + 1) + kFileName;
}

void* open_library(const std::string& path, std::string* error) {
  HMODULE library = LoadLibraryA(path.c_str());
  if (library == nullptr) *error = "Windows error " + std::to_string(GetLastError());
  return reinterpret_cast<void*>(library);
}

void* symbol(void* library, const char* name) {
  return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(library), name));
}
#else
constexpr char kFileName[] = "libfrusta_bake.so";

std::string beside_this_module() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&beside_this_module), &info) == 0 || info.dli_fname == nullptr)
    return kFileName;
  const std::string module = info.dli_fname;
  const size_t slash = module.find_last_of('/');
  return slash == std::string::npos ? kFileName : module.substr(0, slash + 1) + kFileName;
}

void* open_library(const std::string& path, std::string* error) {
  void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) *error = dlerror();
  return library;
}

void* symbol(void* library, const char* name) { return dlsym(library, name); }
#endif

struct Loaded {
  BakePlugin plugin;
  bool ok = false;
  std::string why;
};

Loaded load() {
  Loaded out;
  const char* chosen = std::getenv("FRUSTA_BAKE_PLUGIN");
  const std::string beside = beside_this_module();
  std::string error;
  void* library = nullptr;
  if (chosen != nullptr && *chosen != 0) {
    library = open_library(chosen, &error);
    if (library == nullptr) {
      out.why = std::string("FRUSTA_BAKE_PLUGIN names ") + chosen + ", which did not load: " + error;
      return out;
    }
  } else {
    library = open_library(beside, &error);
    if (library == nullptr) {
      std::string system_error;
      library = open_library(kFileName, &system_error);
      if (library == nullptr) {
        out.why = std::string("the baker library (") + kFileName +
                  ") is not installed beside the runtime (" + error +
                  "): it is built only where Embree exists; bake with frusta-bake there and "
                  "load the .frtree file";
        return out;
      }
    }
  }
  const auto version = reinterpret_cast<decltype(&frusta_bake_plugin_version)>(
      symbol(library, "frusta_bake_plugin_version"));
  out.plugin.bake = reinterpret_cast<decltype(&frusta_bake_plugin_bake)>(
      symbol(library, "frusta_bake_plugin_bake"));
  out.plugin.free = reinterpret_cast<decltype(&frusta_bake_plugin_free)>(
      symbol(library, "frusta_bake_plugin_free"));
  if (version == nullptr || out.plugin.bake == nullptr || out.plugin.free == nullptr) {
    out.why = "the baker library found lacks the plugin's functions: not a Frusta baker";
    return out;
  }
  if (version() != FRUSTA_BAKE_PLUGIN_VERSION) {
    out.why = "the baker library speaks plugin version " + std::to_string(version()) +
              ", this runtime " + std::to_string(FRUSTA_BAKE_PLUGIN_VERSION) +
              ": install the two from one build";
    return out;
  }
  out.ok = true;  // kept loaded for the process's life
  return out;
}

}  // namespace

const BakePlugin* bake_plugin(std::string* why) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.ok) *why = loaded.why;
  return loaded.ok ? &loaded.plugin : nullptr;
}

}  // namespace frusta
