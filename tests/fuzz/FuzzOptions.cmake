# VOLSG_FUZZ=ON (clang only): the whole build is instrumented for libFuzzer's coverage and runs
# under ASan+UBSan; tests/fuzz adds one fuzzer executable per input format (.ci/fuzz).
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "VOLSG_FUZZ=ON needs clang: configure with CC=clang CXX=clang++")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
  -fno-sanitize-recover=undefined)
add_link_options(-fsanitize=address,undefined)
