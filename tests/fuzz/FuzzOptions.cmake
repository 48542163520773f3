# VOLSG_FUZZ=ON (clang only): the whole build is instrumented for libFuzzer's coverage and runs
# under ASan+UBSan; tests/fuzz adds one fuzzer executable per input format (.ci/fuzz). The
# tests and programs link without libFuzzer (the coverage hooks are the sanitizer runtime's);
# running the suite in such a build needs -ffp-contract=off as well (gcc's ISO-mode default),
# since kernels at different SIMD levels are tested to agree bit for bit.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "VOLSG_FUZZ=ON needs clang: configure with CC=clang CXX=clang++")
endif()
# VOLSG_FUZZ_COVERAGE: "full" is libFuzzer's own instrumentation (counters, comparison and
# indirect-call tracing), for long runs; "counters" keeps the edge counters and their table
# only, which still guide libFuzzer, without a callback on every comparison (the sanitizer
# suite that shares the build in CI runs that much faster).
set(VOLSG_FUZZ_COVERAGE "full" CACHE STRING "libFuzzer instrumentation: full or counters")
if(VOLSG_FUZZ_COVERAGE STREQUAL "counters")
  add_compile_options(-fsanitize-coverage=inline-8bit-counters,pc-table)
elseif(VOLSG_FUZZ_COVERAGE STREQUAL "full")
  add_compile_options(-fsanitize=fuzzer-no-link)
else()
  message(FATAL_ERROR "VOLSG_FUZZ_COVERAGE is full or counters, not '${VOLSG_FUZZ_COVERAGE}'")
endif()
add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer
  -fno-sanitize-recover=undefined)
add_link_options(-fsanitize=address,undefined)
