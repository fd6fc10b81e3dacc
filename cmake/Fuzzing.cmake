# SNELL_FUZZ=ON: every target is instrumented for libFuzzer's coverage and checked by AddressSanitizer
# and UndefinedBehaviorSanitizer (libFuzzer ships with Debian's libclang-rt-14-dev). Only clang has
# libFuzzer, so configure with -DCMAKE_CXX_COMPILER=clang++ (tools/fuzz.sh does).
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "SNELL_FUZZ=ON needs clang: configure with -DCMAKE_CXX_COMPILER=/usr/bin/clang++")
endif()
# Any undefined behaviour stops the run like a crash, so the fuzzer reports it and keeps a reproducer.
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
  -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
