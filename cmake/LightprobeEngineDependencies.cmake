# The libraries the engine links, one list for building it (engine/CMakeLists.txt, the top-level
# CMakeLists.txt) and for a program that uses the installed package (LightprobeConfig.cmake).
# `find_command` finds one package: lightprobe_require_package while building, find_dependency in the
# package. A library whose target is already defined is not looked for again.
# Each entry: the target the engine links | the package | its version, if one is required.
set(LIGHTPROBE_ENGINE_DEPENDENCIES "Threads::Threads|Threads" "TBB::tbb|TBB" "embree|embree|3"
    "OpenEXR::OpenEXR|OpenEXR" "Imath::Imath|Imath" "tinyobjloader::tinyobjloader|tinyobjloader" "fmt::fmt|fmt"
    "nlohmann_json::nlohmann_json|nlohmann_json" "DNNL::dnnl|dnnl" "JPEG::JPEG|JPEG")

macro(lightprobe_find_engine_dependencies find_command)
  foreach(_lightprobe_entry IN LISTS LIGHTPROBE_ENGINE_DEPENDENCIES)
    string(REPLACE "|" ";" _lightprobe_entry "${_lightprobe_entry}")
    list(POP_FRONT _lightprobe_entry _lightprobe_target)
    if(NOT TARGET ${_lightprobe_target})
      cmake_language(CALL ${find_command} ${_lightprobe_entry})
    endif()
  endforeach()
  if(NOT TARGET PkgConfig::STB)  # stb (stb_image_write) has no CMake package: Debian ships a .pc file
    cmake_language(CALL ${find_command} PkgConfig)
    pkg_check_modules(STB REQUIRED QUIET IMPORTED_TARGET stb)
  endif()
  if(NOT TARGET PkgConfig::WEBP)  # libwebp and its animation encoder (libwebpmux): pkg-config files only
    cmake_language(CALL ${find_command} PkgConfig)
    pkg_check_modules(WEBP REQUIRED QUIET IMPORTED_TARGET libwebp libwebpmux)
  endif()
  # tinygltf is used header-only: engine/model/tinygltf_implementation.cpp compiles it (with stb_image
  # from libstb and nlohmann_json). Only its header is looked for, not Debian's prebuilt library.
  if(NOT LIGHTPROBE_TINYGLTF_INCLUDE_DIR)
    find_path(LIGHTPROBE_TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)
  endif()
endmacro()

macro(lightprobe_require_package)
  find_package(${ARGV} REQUIRED)
endmacro()
