# Build speed (docs/performance.md, "Build and test budgets"). Measured on the 2-core
# machine, the program alone from scratch: 230 s with Ninja and none of this, 92 s with it.
#
# - Unity builds: each layer's sources compiled as batches of CMAKE_UNITY_BUILD_BATCH_SIZE
#   files, so the templates they share (Eigen's expressions, std::vector, the json
#   parser) are instantiated and optimised once per batch instead of once per file
#   (230 -> 100 s). A name at namespace scope must therefore be unique in its layer, and
#   a test file keeps its helpers in a namespace of its own (tests/CMakeLists.txt).
#   -DCMAKE_UNITY_BUILD=OFF builds file by file (a file that needs an include it does
#   not name, or an overload that a neighbour's function would capture, shows there).
#   The instrumented build used to, and it became CI's slowest phase: 798 s file by
#   file against 553 s in batches (clang, ASan + UBSan + coverage, 2 cores, at 3c2da06);
#   the sanitizers' reports keep their file:line through a batch's #include.
# - Precompiled headers: the standard library and Eigen's core parsed once per build, not
#   once per batch (src/CMakeLists.txt, tests/CMakeLists.txt); FSICONTACT_PCH=OFF to
#   disable.
# - ccache, where installed (Debian's ccache; never required): a rebuild of unchanged
#   sources comes from its cache. Its sloppiness lets it cache compilations that use a
#   precompiled header.
if(NOT DEFINED CMAKE_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
endif()
if(NOT DEFINED CMAKE_UNITY_BUILD_BATCH_SIZE)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()
option(FSICONTACT_PCH "Precompiled headers for the standard library, Eigen and GoogleTest" ON)
# What nearly every file of ours includes; the tests add GoogleTest and the json reader.
set(FSICONTACT_PCH_HEADERS <algorithm> <array> <cmath> <cstdio> <functional> <map> <memory> <optional>
    <stdexcept> <string> <utility> <vector> <Eigen/Core> <Eigen/SparseCore>)

find_program(FSICONTACT_CCACHE ccache)
if(FSICONTACT_CCACHE AND NOT DEFINED CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${FSICONTACT_CCACHE})
endif()
