# Sanitizer and fuzzer builds (scripts/test.sh runs both in CI; README "Tests" says how by hand).
#
# PF_SANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer (+ float-cast-overflow, which
# -fsanitize=undefined leaves out on GCC) on every target of this tree, and the first report
# aborts the program (-fno-sanitize-recover=all), so a report is a failed test, not a log line.
# Use a separate build tree (build-asan/): the flags apply to the whole tree.
#
# PF_FUZZ (automatic): the libFuzzer target pf_scene_fuzz is built when the C++ compiler is
# clang and can link -fsanitize=fuzzer; tests/fuzz/CMakeLists.txt reads PF_FUZZ.
option(PF_SANITIZE "Build everything with -fsanitize=address,undefined,float-cast-overflow" OFF)

if(PF_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "PF_SANITIZE needs GCC or Clang")
  endif()
  set(PF_SANITIZE_FLAGS -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
                        -fno-omit-frame-pointer)
  add_compile_options(${PF_SANITIZE_FLAGS})
  add_link_options(${PF_SANITIZE_FLAGS})
  # -O1 and line tables only (after the build type's -O2 -g, so they win): what ASan's reports
  # need, and half the compile time of the instrumented test suites (test_api_validation.cpp:
  # 26.7 s at -O2 -g, 14.2 s at -O1 -g1, 2026-11-26), which was most of CI's sanitizer build.
  # The GoogleTest programs' own files go further, to -O0 (tests/CMakeLists.txt says which keep -O1).
  add_compile_options(-O1 -g1)
  message(STATUS "pflip: sanitizers on (${PF_SANITIZE_FLAGS})")
endif()

set(PF_FUZZ OFF)
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer")
  set(CMAKE_REQUIRED_QUIET ON)
  check_cxx_source_compiles([[
    #include <cstddef>
    #include <cstdint>
    extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }
  ]] PF_HAS_LIBFUZZER)
  unset(CMAKE_REQUIRED_FLAGS)
  unset(CMAKE_REQUIRED_QUIET)
  set(PF_FUZZ ${PF_HAS_LIBFUZZER})
endif()
