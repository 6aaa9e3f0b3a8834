# The instrumented build (make check-instrumented, docs/reliability.md): one build that
# serves both the sanitizer suite and the fuzz smoke, where there were two (a g++ build
# of the suite with ASan + UBSan, and a clang build of the program for the fuzzers).
#
#   FSICONTACT_SANITIZE  AddressSanitizer and UBSan over all of our code
#   FSICONTACT_FUZZ      coverage instrumentation for libFuzzer, and the fuzz targets
#                        (fuzz/); needs clang, implies FSICONTACT_SANITIZE
#
# -O1 and line tables only: sanitizer reports need file:line in their stack traces, not
# variables, and full debug information cost more compile time than the rest (measured,
# docs/performance.md). NDEBUG is never defined here, so Eigen's assertions (bounds,
# sizes) stay on: one found the IQN-ILS column count (86a6575).
if(FSICONTACT_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "FSICONTACT_FUZZ needs clang++ (-DCMAKE_CXX_COMPILER=clang++)")
endif()
if(FSICONTACT_FUZZ)
  set(FSICONTACT_SANITIZE ON)
endif()
if(FSICONTACT_SANITIZE)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options(-O1 -gline-tables-only)
  else()
    add_compile_options(-O1 -g1)
  endif()
  add_compile_options(-fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(FSICONTACT_FUZZ)
  # Everything of ours feeds the fuzzer's coverage; its main is linked into the fuzz
  # targets only (fuzz/CMakeLists.txt), so the tests and the program keep their own.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
