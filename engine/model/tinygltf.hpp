#pragma once
// tinygltf as the engine configures it, for every file that includes it (the class's defaults depend on
// these): it reads no file and decodes no image itself. Files come through our callbacks (ModelFiles:
// confined to the model's folder, bounded) and images stay encoded for engine/texture.
#include <fstream>  // tinygltf's writer needs it even without its file system functions

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>
