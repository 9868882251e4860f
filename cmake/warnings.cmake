# The warnings every target of the project compiles with (link `lightprobe_warnings` privately).
include_guard(GLOBAL)
add_library(lightprobe_warnings INTERFACE)
target_compile_options(lightprobe_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                                     -Wno-sign-conversion)
