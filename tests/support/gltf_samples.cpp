#include "support/gltf_samples.hpp"

#include <algorithm>
#include <filesystem>

#include "support/test_data.hpp"

namespace lp::test {

const std::map<std::string, size_t>& valid_gltf_samples() {
  static const std::map<std::string, size_t> valid = {
      {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496},
      {"glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12},
      {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", 12},  // TEXCOORD_1
      {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", 12},
      {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", 12},
      {"glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12},
      {"glTF2/BoxTextured-glTF/BoxTextured.gltf", 12},
      {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", 37116},
      {"glTF2/cameras/Cameras.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 2},  // triangle strip
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 2},  // triangle fan
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_11.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf", 2},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_15.gltf", 2},
      {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12},
      {"glTF2/issue_3269/texcoord_crash.gltf", 10},
      {"glTF2/simple_skin/simple_skin.gltf", 8},
      {"glTF2/textureTransform/TextureTransformTest.gltf", 24},
  };
  return valid;
}

// Refused files and the kind of error: malformed ones Corrupt, a missing buffer NotFound, glTF 1.0 and
// the extensions we do not read Unsupported.
const std::map<std::string, ErrorKind>& refused_gltf_samples() {
  static const std::map<std::string, ErrorKind> refused = {
      {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf",
       ErrorKind::Unsupported},  // required extension
      {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", ErrorKind::Corrupt},
      {"glTF2/IncorrectVertexArrays/Cube.gltf", ErrorKind::Corrupt},
      {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", ErrorKind::Corrupt},
      {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", ErrorKind::Corrupt},
      {"glTF2/MissingBin/BoxTextured.gltf", ErrorKind::NotFound},
      {"glTF2/RecursiveNodes/RecursiveNodes.gltf", ErrorKind::Corrupt},
      {"glTF2/SchemaFailures/sceneWrongType.gltf", ErrorKind::Corrupt},
      {"glTF2/TestNoRootNode/NoScene.gltf", ErrorKind::Corrupt},
      {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", ErrorKind::Corrupt},
      {"glTF2/draco/2CylinderEngine.gltf",
       ErrorKind::Corrupt},  // Draco-compressed: its accessors have no buffer view
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf",
       ErrorKind::Corrupt},  // points only
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf",
       ErrorKind::Corrupt},  // lines only
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", ErrorKind::Corrupt},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", ErrorKind::Corrupt},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", ErrorKind::Corrupt},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", ErrorKind::Corrupt},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", ErrorKind::Corrupt},
      {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badArray.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badExtension.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badNumber.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badObject.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badString.gltf", ErrorKind::Corrupt},
      {"glTF2/wrongTypes/badUint.gltf", ErrorKind::Corrupt},
      // glTF 1.0, well-formed or not.
      {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", ErrorKind::Unsupported},
      {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", ErrorKind::Unsupported},
      {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", ErrorKind::Unsupported},
      {"glTF/BoxTextured-glTF/BoxTextured.gltf", ErrorKind::Unsupported},
      {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", ErrorKind::Unsupported},
      {"glTF/IncorrectVertexArrays/Cube_v1.gltf", ErrorKind::Unsupported},
      {"glTF/TwoBoxes/TwoBoxes.gltf", ErrorKind::Unsupported},
  };
  return refused;
}

std::vector<std::string> gltf_sample_files() {
  std::vector<std::string> files;
  const auto models = assimp_model_path("");
  for (const char* root : {"glTF2", "glTF"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(models / root)) {
      const auto ext = entry.path().extension();
      if (ext == ".gltf" || ext == ".glb") files.push_back(entry.path().lexically_relative(models).string());
    }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace lp::test
