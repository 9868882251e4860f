# -DLIGHTPROBE_FUZZ=ON: every library is compiled with libFuzzer's coverage instrumentation and with
# AddressSanitizer and UndefinedBehaviorSanitizer; tests/fuzz builds one libFuzzer binary per target.
# Clang only (GCC has no libFuzzer); the normal build does not need clang.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "LIGHTPROBE_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++; scripts/setup --fuzz "
                      "installs it), not ${CMAKE_CXX_COMPILER_ID}")
endif()
# Any UBSan report aborts, so libFuzzer keeps it as a crash like an ASan report.
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
