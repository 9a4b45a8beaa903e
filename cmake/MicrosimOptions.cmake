# Build options of microsim, all namespaced MICROSIM_*.
option(MICROSIM_BUILD_TESTS "Build the GoogleTest suites and register them with CTest" ON)
option(MICROSIM_BUILD_BENCHMARKS "Build the benchmark programs behind 'microsim-cli bench'" ON)
option(MICROSIM_WERROR "Treat compiler warnings as errors" OFF)
set(MICROSIM_SANITIZE "" CACHE STRING
  "Sanitizers: empty, 'address' (address+undefined), 'thread', or 'fuzzer' (clang: libFuzzer coverage + address+undefined)")
set_property(CACHE MICROSIM_SANITIZE PROPERTY STRINGS "" address thread fuzzer)

if(MICROSIM_SANITIZE STREQUAL "address")
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
elseif(MICROSIM_SANITIZE STREQUAL "thread")
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
elseif(MICROSIM_SANITIZE STREQUAL "fuzzer")
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MICROSIM_SANITIZE=fuzzer needs clang (libFuzzer); use the 'sanitize' preset")
  endif()
  # every library is instrumented for coverage; only the fuzz executables link libFuzzer's main
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined
                      -fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/tests/sanitizers/eigen.ignorelist
                      -fsanitize-coverage-ignorelist=${PROJECT_SOURCE_DIR}/tests/sanitizers/eigen-coverage.ignorelist)
  add_link_options(-fsanitize=address,undefined)
elseif(NOT MICROSIM_SANITIZE STREQUAL "")
  message(FATAL_ERROR "MICROSIM_SANITIZE must be empty, 'address', 'thread' or 'fuzzer', not '${MICROSIM_SANITIZE}'")
endif()

# ccache, when installed, lets the several build trees (presets, sanitizer runs) share
# compiled objects; the build never depends on it.
option(MICROSIM_USE_CCACHE "Compile through ccache when it is installed" ON)
if(MICROSIM_USE_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(MICROSIM_CCACHE ccache)
  if(MICROSIM_CCACHE)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${MICROSIM_CCACHE})
  endif()
endif()
