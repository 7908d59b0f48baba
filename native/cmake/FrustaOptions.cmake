# SPDX-License-Identifier: MIT
# Compiler settings every Frusta target shares.

# frusta_target_options(target): warnings, determinism flags and sanitizers.
function(frusta_target_options target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion)
    # determinism: no fused multiply-add, so every machine rounds alike (box2d does the same)
    target_compile_options(${target} PRIVATE -ffp-contract=off)
    if(FRUSTA_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
  if(FRUSTA_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=all
                                             -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(FRUSTA_SANITIZE_THREAD)
    target_compile_options(${target} PRIVATE -fsanitize=thread -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=thread)
  endif()
  if(FRUSTA_SANITIZE OR FRUSTA_SANITIZE_THREAD)
    # a sanitized Debug build compiles the libraries (the engine, the baker, the test
    # scenes) at -O1, as ASan's authors advise, and the programs at -O0: under ASan
    # the unit tests took 298 s all at -O0, 78 s so, and 60 s all at -O1, which
    # took 257 s to build instead of 150 (the test programs are big and run little).
    # A sanitizer's report needs line tables only (-g1): 15 % less to compile.
    get_target_property(type ${target} TYPE)
    if(NOT type STREQUAL "EXECUTABLE")
      target_compile_options(${target} PRIVATE "$<$<CONFIG:Debug>:-O1;-g1>")
    endif()
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      # optimised and instrumented, GCC 12 finds uninitialised members inside
      # libstdc++'s std::regex that are not there (GCC bug 105562); the unsanitised
      # builds keep the warning
      target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
    endif()
  endif()
endfunction()

# frusta_full_optimisation(target): the contact pipeline at -O3 in the optimised build a
# user ships (RelWithDebInfo: the Unity package's libraries), as tools/bench measures it
# (Release). At -O2 GCC 12 kept the tree walk's node test out of line and the QP's loops
# rolled: the 10^4-leaf grasp ran 15 % more instructions and 9 % more time a step.
function(frusta_full_optimisation target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE "$<$<CONFIG:RelWithDebInfo>:-O3>")
  endif()
endfunction()
