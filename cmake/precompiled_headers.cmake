# Precompiled headers. Nearly every translation unit parses Eigen and a dozen standard headers
# (several seconds of each file's compile before any of its own code), every test file
# GoogleTest, every binding file pybind11. `animkit_precompile_headers(target [headers...])`
# parses them once per target instead, the target's own headers first (pybind11 wants Python.h
# before any standard header). Only targets with many files use it: a precompiled header costs
# about one ordinary compile to build.
# https://cmake.org/cmake/help/v3.25/command/target_precompile_headers.html
option(ANIMKIT_PRECOMPILE_HEADERS "Precompile Eigen, standard, GoogleTest and pybind11 headers" ON)

set(ANIMKIT_COMMON_HEADERS
    <algorithm> <array> <cmath> <cstdint> <filesystem> <limits> <memory> <optional> <span>
    <string> <string_view> <utility> <variant> <vector>
    <Eigen/Core> <Eigen/Geometry>)

function(animkit_precompile_headers target)
  if(ANIMKIT_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN} ${ANIMKIT_COMMON_HEADERS})
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      # Through a precompiled header GCC 12 reports its false `"text" + std::string` memcpy
      # overflow (GCC bugs 105329 and 105651, fixed in 13) in files that compiled cleanly
      # without one (seen in tests/cli/reliability_cli_test.cpp).
      target_compile_options(${target} PRIVATE -Wno-restrict -Wno-stringop-overflow)
    endif()
  endif()
endfunction()
