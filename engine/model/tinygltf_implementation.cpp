// tinygltf's implementation, compiled once, in the configuration of tinygltf.hpp.
#define TINYGLTF_IMPLEMENTATION
#include "engine/model/tinygltf.hpp"
