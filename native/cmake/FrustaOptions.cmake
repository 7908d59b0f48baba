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
  if((FRUSTA_SANITIZE OR FRUSTA_SANITIZE_THREAD) AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # optimised and instrumented, GCC 12 finds uninitialised members inside libstdc++'s
    # std::regex that are not there (GCC bug 105562); the unsanitised builds keep the
    # warning
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
endfunction()
