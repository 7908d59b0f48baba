# SPDX-License-Identifier: MIT
# The layering of native/src, checked on every source: a folder includes only the folders
# below it, and only the C ABI (capi/) sees the public header. Run as
#   cmake -DSOURCE_DIR=native/src -P layers.cmake
cmake_minimum_required(VERSION 3.22)  # IN_LIST, and empty list elements kept
# Lower layers first; each may include itself and what its line names.
set(allowed
  "core:"
  "geometry:core"
  "spheretree:core geometry"
  "hand:core geometry"
  "tracking:core geometry hand"
  "bake:core geometry spheretree"
  "solver:core geometry spheretree hand"
  "forces:core geometry spheretree hand solver"
  "port:core geometry hand solver forces"
  "runtime:core geometry spheretree hand tracking solver forces port"
  "devices:core geometry hand solver forces port"
  "capi:core geometry spheretree hand tracking bake solver forces port runtime devices frusta")

set(violations "")
set(known "")
foreach(rule IN LISTS allowed)
  string(REPLACE ":" ";" parts "${rule}")
  list(GET parts 0 layer)
  list(LENGTH parts n)
  set(may "${layer}")
  if(n GREATER 1)
    list(GET parts 1 below)
    separate_arguments(below)
    list(APPEND may ${below})
  endif()
  list(APPEND known ${layer})
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${layer}/*.h" "${SOURCE_DIR}/${layer}/*.cpp")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" folder "${line}")
      if(NOT folder IN_LIST may)
        file(RELATIVE_PATH shown "${SOURCE_DIR}" "${source}")
        string(APPEND violations "  ${shown}: ${line} (${layer}/ may include: ${may})\n")
      endif()
    endforeach()
  endforeach()
endforeach()

# every folder is a layer of the table: a new one must be placed in it
file(GLOB folders LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*")
foreach(folder IN LISTS folders)
  if(IS_DIRECTORY "${SOURCE_DIR}/${folder}" AND NOT folder IN_LIST known)
    string(APPEND violations "  ${folder}/: a folder the layering does not place\n")
  endif()
endforeach()

if(violations)
  message(FATAL_ERROR "native/src breaks its layering:\n${violations}")
endif()
message(STATUS "native/src keeps its layering")
