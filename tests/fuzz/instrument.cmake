# SPDX-License-Identifier: MIT
# Included by the top-level CMakeLists.txt when FRUSTA_BUILD_FUZZERS is on, before any
# target exists. A fuzzer is only as good as the coverage it sees: every object in this
# build (the engine, the baker's mesh checks, the glTF loader and tinygltf itself) is
# compiled with coverage, ASan and UBSan. Only the harnesses (tests/fuzz) link
# libFuzzer's main, with -fsanitize=fuzzer.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "FRUSTA_BUILD_FUZZERS needs Clang (CC=clang-14 CXX=clang++-14)")
endif()
# UBSan must stop the run, or libFuzzer never hears of undefined behaviour; -O1 in
# Debug keeps asserts on at a usable speed
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer $<$<CONFIG:Debug>:-O1>)
add_link_options(-fsanitize=address,undefined)

# Debian ships tinygltf as an uninstrumented shared library, where all of the JSON
# parsing happens. Build it here from its header instead (as its README.Debian allows,
# with the same nlohmann-json and stb), under the name the loader links, so that
# find_package(TinyGLTF) in tools/bake takes this one.
if(FRUSTA_BUILD_TOOLS)
  find_path(FRUSTA_STB_INCLUDE stb_image.h PATH_SUFFIXES stb REQUIRED)
  find_library(FRUSTA_STB_LIBRARY stb REQUIRED)
  find_package(nlohmann_json 3 CONFIG REQUIRED)
  add_library(frusta_fuzz_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/tinygltf_impl.cpp)
  target_include_directories(frusta_fuzz_tinygltf SYSTEM PRIVATE ${FRUSTA_STB_INCLUDE})
  target_link_libraries(frusta_fuzz_tinygltf PUBLIC nlohmann_json::nlohmann_json
                                                    ${FRUSTA_STB_LIBRARY})
  add_library(TinyGLTF::TinyGLTF ALIAS frusta_fuzz_tinygltf)
endif()
