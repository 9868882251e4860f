# The version of Lightprobe: the project's, the engine's and the installed CMake package's.
set(LIGHTPROBE_VERSION 0.1.0)
