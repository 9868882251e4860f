// The asset archive unpacker and the model-file rule on archives built here and on the committed fuzz
// corpus (its reproducers included), and asset mesh paths resolving to .glb and .gltf models in a real
// state directory.
#include "server/assets/archive_unpacker.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "api/api_error.hpp"
#include "server/assets/asset_folder.hpp"
#include "server/assets/mesh_paths.hpp"
#include "server/assets/stored_assets.hpp"
#include "support/archive_builder.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;
using test::ArchiveFormat;
using test::file_member;

constexpr ArchiveLimits kLimits{1 << 20, 100};

std::span<const uint8_t> bytes_of(const std::string& s) {
  return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

// The error an unpack of `archive` ends with (its code, and its message in `message`).
api::ErrorCode refusal(const std::vector<uint8_t>& archive, std::string* message = nullptr) {
  const test::TempDir dir;
  try {
    unpack_archive(archive, dir.path(), kLimits);
  } catch (const api::ApiError& e) {
    if (message) *message = e.what();
    return e.code();
  }
  ADD_FAILURE() << "unpacked without an error";
  return api::ErrorCode::Internal;
}

std::vector<UnpackedFile> files(std::vector<std::string> paths) {
  std::vector<UnpackedFile> out;
  for (auto& p : paths) out.push_back({std::move(p), 1});
  return out;
}

std::string model_of(std::vector<std::string> paths) {
  return find_model_file(files(std::move(paths)));
}

std::string refusal_of(std::vector<std::string> paths) {
  try {
    model_of(std::move(paths));
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.code(), api::ErrorCode::InvalidArgument);
    return e.what();
  }
  ADD_FAILURE() << "a model file was found";
  return "";
}

TEST(ArchiveUnpacker, WritesEveryFileWithItsBytesAndDropsDotComponents) {
  const test::TempDir dir;
  const std::string archive = test::make_archive(
      ArchiveFormat::TarGz, {test::folder_member("./car/"), file_member("./car/car.obj", "v 0 0 0\n"),
                             file_member("car//tex/./a.png", "png"), file_member("car/empty.txt", "")});
  const auto written = unpack_archive(bytes_of(archive), dir.path(), kLimits);
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[0].path, "car/car.obj");
  EXPECT_EQ(written[0].bytes, 8);
  EXPECT_EQ(written[1].path, "car/tex/a.png");
  EXPECT_EQ(written[1].bytes, 3);
  EXPECT_EQ(written[2].bytes, 0);
  EXPECT_EQ(fs::file_size(dir.path() / "car" / "tex" / "a.png"), 3u);
}

// The bytes are counted as they are read: a member of 4 MiB of zeros stops at the 1 MiB limit, and no
// more than one read block past it reaches the disk.
TEST(ArchiveUnpacker, StopsWritingOnceTheUnpackedBytesPassTheLimit) {
  const test::TempDir dir;
  test::ArchiveMember zeros = file_member("zeros.bin", "");
  zeros.zero_bytes = 4 << 20;
  const std::string archive = test::make_archive(ArchiveFormat::Zip, {zeros});
  EXPECT_LT(archive.size(), 16u << 10);
  try {
    unpack_archive(bytes_of(archive), dir.path(), kLimits);
    ADD_FAILURE() << "unpacked 4 MiB under a 1 MiB limit";
  } catch (const api::ApiError& e) {
    EXPECT_EQ(e.code(), api::ErrorCode::TooLarge);
  }
  EXPECT_LE(fs::file_size(dir.path() / "zeros.bin"), uint64_t(kLimits.max_bytes));
}

TEST(ArchiveUnpacker, TheMemberLimitCountsFolders) {
  std::vector<test::ArchiveMember> members;
  for (int i = 0; i <= kLimits.max_members; ++i) members.push_back(test::folder_member(std::to_string(i)));
  const std::string archive = test::make_archive(ArchiveFormat::Tar, members);
  EXPECT_EQ(refusal({archive.begin(), archive.end()}), api::ErrorCode::TooLarge);
}

TEST(ArchiveUnpacker, AMemberTwiceOrAFileUnderAFileIsRefused) {
  std::string message;
  const std::string twice =
      test::make_archive(ArchiveFormat::Tar, {file_member("a.obj", "1"), file_member("a.obj", "2")});
  EXPECT_EQ(refusal({twice.begin(), twice.end()}, &message), api::ErrorCode::InvalidArgument);
  EXPECT_NE(message.find("'a.obj' appears twice"), std::string::npos) << message;
  const std::string under =
      test::make_archive(ArchiveFormat::Tar, {file_member("a", "1"), file_member("a/b.obj", "2")});
  EXPECT_EQ(refusal({under.begin(), under.end()}, &message), api::ErrorCode::InvalidArgument);
  EXPECT_NE(message.find("conflicts with a file"), std::string::npos) << message;
}

// The committed corpus of the fuzz target, reproducers included: each unpacks or is refused as stated.
TEST(ArchiveUnpacker, TheFuzzCorpusUnpacksOrIsRefusedAsExpected) {
  const auto corpus = [](const std::string& file) {
    return test::read_bytes(test::fuzz_corpus_path("archive_unpacker", file));
  };
  for (const std::string file : {"folder.tar", "folder.tar.gz", "top_level.zip"}) {
    const test::TempDir dir;
    const auto written = unpack_archive(corpus(file), dir.path(), kLimits);
    EXPECT_FALSE(find_model_file(written).empty()) << file;
  }
  std::string message;
  EXPECT_EQ(refusal(corpus("folder_with_link.zip"), &message), api::ErrorCode::InvalidArgument);
  EXPECT_NE(message.find("'car/link.obj' is a symbolic link"), std::string::npos) << message;
  EXPECT_EQ(refusal(corpus("dotdot_member.tar"), &message), api::ErrorCode::InvalidArgument);
  EXPECT_NE(message.find("'..' component"), std::string::npos) << message;
}

TEST(AssetModelFile, IsTheOneAtTheTopLevelOrInsideTheOneTopFolder) {
  EXPECT_EQ(model_of({"model.OBJ", "model.mtl", "tex/a.png", "lod/low.obj"}), "model.OBJ");
  EXPECT_EQ(model_of({"car/car.gltf", "car/car.bin", "car/lod/low.obj"}), "car/car.gltf");
  EXPECT_EQ(model_of({"car/scene.glb"}), "car/scene.glb");
  EXPECT_NE(refusal_of({"a.obj", "b.glb"}).find("2 model files: 'a.obj', 'b.glb'"), std::string::npos);
  EXPECT_NE(refusal_of({"car/a.obj", "car/b.obj"}).find("2 model files"), std::string::npos);
  EXPECT_NE(refusal_of({"readme.md", "car/car.obj"}).find("nested folders: 'car/car.obj'"),
            std::string::npos);
  EXPECT_NE(refusal_of({"a/x.obj", "b/y.obj"}).find("nested folders"), std::string::npos);
  EXPECT_NE(refusal_of({"tex.png"}).find("no model file among its 1 files"), std::string::npos);
  EXPECT_NE(refusal_of({}).find("no model file among its 0 files"), std::string::npos);
}

// What the renderer will load for a .glb or a .gltf asset: the model file in the asset's folder.
TEST(AssetMeshPaths, GlbAndGltfAssetsResolveToTheirModelFiles) {
  const test::TempDir state;
  Options options;
  options.max_memory_mb = 64;
  App app(options);
  app.state = std::make_unique<StateStore>(state.path());
  const auto file = [](const std::string& name) {
    const auto bytes = test::read_bytes(test::model_path(name));
    return std::string(bytes.begin(), bytes.end());
  };
  const std::string glb = file("quad.glb");
  store_asset(app, "box", bytes_of(glb));
  const std::string gltf = test::make_archive(
      ArchiveFormat::Zip, {file_member("scene/scene.gltf", file("gltf/quad.gltf")),
                           file_member("scene/quad.bin", file("gltf/quad.bin")),
                           file_member("scene/red green.png", file("gltf/red green.png")),
                           file_member("scene/flat_normal.png", file("gltf/flat_normal.png"))});
  store_asset(app, "scene", bytes_of(gltf));
  const fs::path assets = fs::canonical(state.path() / "asset-files");
  EXPECT_EQ(resolve_mesh_path(app, "assets/box", "path"), assets / "box" / "model.glb");
  EXPECT_EQ(resolve_mesh_path(app, "assets/scene", "path"), assets / "scene" / "scene" / "scene.gltf");
  EXPECT_EQ(resolve_mesh_path(app, "assets/scene/scene/quad.bin", "path"),
            assets / "scene" / "scene" / "quad.bin");
  EXPECT_THROW(resolve_mesh_path(app, "assets/scene/../box/model.glb", "path"), api::ApiError);
  EXPECT_THROW(resolve_mesh_path(app, "assets/scene/scene", "path"), api::ApiError);  // a folder
  EXPECT_THROW(resolve_mesh_path(app, "assets/box.glb", "path"), api::ApiError);
  EXPECT_TRUE(remove_asset(app, "box"));
  EXPECT_THROW(resolve_mesh_path(app, "assets/box", "path"), api::ApiError);
}

}  // namespace
}  // namespace lp::server
