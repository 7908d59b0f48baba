# SPDX-License-Identifier: MIT
# Windows x64 (where most Unity editors run) from Debian's mingw-w64 cross compiler, the
# posix-threads flavour that std::thread needs (g++-mingw-w64-x86-64-posix). The
# runtime DLL links libgcc, libstdc++ and winpthread statically, so it ships alone.
# hidapi is Debian's source built for Windows into FRUSTA_WINDOWS_LIBS
# (tools/lib/common.sh: build_windows_libraries). Tests run under Wine.
# tools/test builds build/windows with it.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR AMD64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

# C99 printf (%zu, %lld) rather than msvcrt's; libstdc++ asks for it in C++ anyway
set(CMAKE_C_FLAGS_INIT "-D__USE_MINGW_ANSI_STDIO=1")
set(CMAKE_CXX_FLAGS_INIT "-D__USE_MINGW_ANSI_STDIO=1")

# the Windows build of hidapi (headers, static library, pkg-config file)
set(FRUSTA_WINDOWS_LIBS "" CACHE PATH "Prefix holding hidapi built for Windows")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES FRUSTA_WINDOWS_LIBS)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${FRUSTA_WINDOWS_LIBS})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(ENV{PKG_CONFIG_LIBDIR} "${FRUSTA_WINDOWS_LIBS}/lib/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

# nothing from the MinGW runtime to ship beside the DLL or the test programs
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static")

# Debian's wine64 package has no wrapper on PATH; wine-run starts a listing of a test
# program's tests again where Wine failed to start it
find_program(FRUSTA_WINE64 NAMES wine64 PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(FRUSTA_WINE64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/wine-run ${FRUSTA_WINE64})
endif()
