# VOLSG_FUZZ=ON (clang only): the whole build is instrumented for libFuzzer's coverage and runs
# under ASan+UBSan; tests/fuzz adds one fuzzer executable per input format (.ci/fuzz). The
# tests and programs link without libFuzzer (the coverage hooks are the sanitizer runtime's);
# running the suite in such a build needs -ffp-contract=off as well (gcc's ISO-mode default),
# since kernels at different SIMD levels are tested to agree bit for bit.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "VOLSG_FUZZ=ON needs clang: configure with CC=clang CXX=clang++")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
  -fno-sanitize-recover=undefined)
add_link_options(-fsanitize=address,undefined)
