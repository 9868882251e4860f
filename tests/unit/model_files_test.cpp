// The files a model was read from, as the loader reports them (Model::files): every one, once, the model
// file first, stamped with the size and modification time it had before it was read.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/model/model_loader.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names(const Model& m) {
  std::vector<std::string> out;
  for (const FileStamp& f : m.files) out.push_back(f.path.filename().string());
  return out;
}

TEST(ModelFiles, AGltfReportsItsBufferAndImages) {
  const Model m = load_model(test::model_path("gltf/quad.gltf"), {});
  EXPECT_EQ(names(m),
            (std::vector<std::string>{"quad.gltf", "quad.bin", "red green.png", "flat_normal.png"}));
  for (const FileStamp& f : m.files) {
    EXPECT_EQ(f, FileStamp::of(f.path)) << f.path;
    EXPECT_EQ(f.size, fs::file_size(test::model_path("gltf") / f.path.filename()));
  }
}

TEST(ModelFiles, AnObjReportsItsMaterialLibraryAndTextures) {
  EXPECT_EQ(names(load_model(test::model_path("obj/quad.obj"), {})),
            (std::vector<std::string>{"quad.obj", "quad.mtl", "checker.png", "flat_normal.png"}));
}

// Textures found in a shared cache were not read again, and are reported all the same.
TEST(ModelFiles, TexturesFromTheCacheAreReportedToo) {
  TextureCache cache;
  const Model first = load_model(test::model_path("obj/quad.obj"), {}, &cache);
  const Model second = load_model(test::model_path("obj/quad.obj"), {}, &cache);
  EXPECT_EQ(second.materials[0].base_color->texture, first.materials[0].base_color->texture);
  EXPECT_EQ(second.files, first.files);
}

TEST(ModelFiles, AStampChangesWithTheFile) {
  const test::TempDir dir;
  const fs::path file = dir.path() / "model.mtl";
  std::ofstream(file) << "newmtl m\nKd 1 0 0\n";
  const FileStamp before = FileStamp::of(file);
  EXPECT_EQ(FileStamp::of(file), before);
  EXPECT_EQ(before.size, 18u);
  fs::last_write_time(file, before.modified + std::chrono::seconds(1));
  EXPECT_NE(FileStamp::of(file), before);
  fs::remove(file);
  EXPECT_EQ(FileStamp::of(file), (FileStamp{file}));
}

TEST(ModelFiles, AModelFromMemoryReportsNone) {
  const auto bytes = test::read_bytes(test::model_path("quad.glb"));
  EXPECT_TRUE(load_gltf_memory(bytes, "quad.glb", {}).files.empty());
}

}  // namespace
}  // namespace lp
