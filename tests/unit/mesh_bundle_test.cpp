// Mesh bundles of renders split over machines: the bundle hash over files on disk (independent of the
// order they are listed or were written in and of where the folder lies; changed by any byte, path or
// file), a real OBJ model's bundle written as a tar and unpacked again to the same hash, and the render
// description carrying the bundles of mesh objects.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/model/model_loader.hpp"
#include "server/assets/archive_unpacker.hpp"
#include "server/scale_out/bundle_archive.hpp"
#include "server/scale_out/bundle_hash.hpp"
#include "server/scale_out/mesh_bundles.hpp"
#include "server/scale_out/render_description.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

// A file of more than one of the hash's 1 MiB blocks, so a byte in a later block is covered too.
const std::string kLarge = [] {
  std::string s((1 << 20) + 1000, '\0');
  for (size_t i = 0; i < s.size(); ++i) s[i] = char(i * 7919 % 251);
  return s;
}();

void write(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
}

const std::vector<std::pair<std::string, std::string>> kFiles = {
    {"model.obj", "mtllib model.mtl\nv 0 0 0\n"},
    {"model.mtl", "newmtl a\nmap_Kd tex/a.png\n"},
    {"tex/a.png", kLarge},
    {"tex/b.png", "b"}};

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const auto& [name, bytes] : kFiles) out.push_back(name);
  return out;
}

TEST(BundleHash, IsIndependentOfListingAndWritingOrderAndOfTheFolder) {
  test::TempDir a, b;
  for (const auto& [name, bytes] : kFiles) write(a.path() / name, bytes);
  for (auto it = kFiles.rbegin(); it != kFiles.rend(); ++it) write(b.path() / it->first, it->second);
  const std::string hash = bundle_hash(a.path(), names());
  EXPECT_TRUE(is_bundle_hash(hash)) << hash;
  std::vector<std::string> reversed = names();
  std::reverse(reversed.begin(), reversed.end());
  EXPECT_EQ(bundle_hash(a.path(), reversed), hash);
  EXPECT_EQ(bundle_hash(b.path(), names()), hash);
  EXPECT_EQ(bundle_hash(b.path(), {"tex/b.png", "model.obj", "tex/a.png", "model.mtl", "model.obj"}), hash);
}

TEST(BundleHash, ChangesWithAnyByte) {
  test::TempDir dir;
  for (const auto& [name, bytes] : kFiles) write(dir.path() / name, bytes);
  const std::string hash = bundle_hash(dir.path(), names());
  for (const auto& [name, bytes] : kFiles)
    for (const size_t at : {size_t(0), bytes.size() - 1}) {
      std::string changed = bytes;
      changed[at] = char(changed[at] ^ 1);
      write(dir.path() / name, changed);
      EXPECT_NE(bundle_hash(dir.path(), names()), hash) << name << " byte " << at;
      write(dir.path() / name, bytes);
    }
  write(dir.path() / "tex/b.png", "b ");  // one byte more
  EXPECT_NE(bundle_hash(dir.path(), names()), hash);
  write(dir.path() / "tex/b.png", "b");
  EXPECT_EQ(bundle_hash(dir.path(), names()), hash);
}

TEST(BundleHash, ChangesWithAnyPathOrFile) {
  test::TempDir dir;
  for (const auto& [name, bytes] : kFiles) write(dir.path() / name, bytes);
  const std::string hash = bundle_hash(dir.path(), names());
  fs::rename(dir.path() / "tex/b.png", dir.path() / "tex/c.png");
  EXPECT_NE(bundle_hash(dir.path(), {"model.obj", "model.mtl", "tex/a.png", "tex/c.png"}), hash);
  fs::rename(dir.path() / "tex/c.png", dir.path() / "b.png");
  EXPECT_NE(bundle_hash(dir.path(), {"model.obj", "model.mtl", "tex/a.png", "b.png"}), hash);
  EXPECT_NE(bundle_hash(dir.path(), {"model.obj", "model.mtl", "tex/a.png"}), hash);  // a file less
  write(dir.path() / "tex/b.png", "b");
  EXPECT_NE(bundle_hash(dir.path(), {"model.obj", "model.mtl", "tex/a.png", "tex/b.png", "b.png"}), hash);
  EXPECT_EQ(bundle_hash(dir.path(), names()), hash);
  EXPECT_THROW(bundle_hash(dir.path(), {"model.obj", "missing.png"}), std::runtime_error);
}

TEST(BundleHash, HasOneForm) {
  const std::string hex(64, 'a');
  EXPECT_TRUE(is_bundle_hash("0123456789abcdef" + std::string(48, 'e') + "-bundle"));
  for (const std::string& bad : std::vector<std::string>{
           std::string(), hex + "-64x32", std::string(64, 'A') + "-bundle", hex.substr(1) + "-bundle",
           hex + "0-bundle", "0123456789abcdef-bundle", "../" + hex.substr(3) + "-bundle", hex + "-bundle/x",
           hex.substr(1) + "g-bundle"})
    EXPECT_FALSE(is_bundle_hash(bad)) << bad;
}

TEST(MeshBundle, AnObjModelsTarUnpacksToTheSameHash) {
  const Model model = load_model(test::model_path("obj/quad.obj"), ModelLimits{});
  const MeshBundle bundle = mesh_bundle(model);
  EXPECT_EQ(bundle.model, "quad.obj");
  std::vector<std::string> sorted = bundle.files;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<std::string>{"checker.png", "flat_normal.png", "quad.mtl", "quad.obj"}));
  EXPECT_EQ(bundle.hash, bundle_hash(test::model_path("obj"), sorted));

  const BundleSize size = bundle_size(bundle);
  const auto tar = write_bundle_tar(bundle, size);
  EXPECT_LE(int64_t(tar.size()), size.tar_bytes);
  test::TempDir dir;
  std::vector<std::string> unpacked;
  for (const auto& file : unpack_archive(tar, dir.path(), {1 << 20, 16})) unpacked.push_back(file.path);
  EXPECT_EQ(unpacked, bundle.files);  // in the bundle's order, the model file first
  EXPECT_EQ(bundle_hash(dir.path(), unpacked), bundle.hash);
  const Model again = load_model(dir.path() / bundle.model, ModelLimits{});
  EXPECT_EQ(again.triangle_count(), model.triangle_count());
  EXPECT_EQ(again.files.size(), model.files.size());
}

TEST(RenderDescription, CarriesTheMeshBundles) {
  const std::string bundle = "0123456789abcdef" + std::string(48, 'e') + "-bundle";
  const RenderDescription d{nlohmann::json{{"spp", 4}},
                            std::string(64, 'e') + "-8x4",
                            "http://127.0.0.1:1",
                            {{2, bundle, "dir/quad.obj"}}};
  const RenderDescription back = parse_description(description_json(d));
  EXPECT_EQ(back.request, d.request);
  ASSERT_EQ(back.meshes.size(), 1u);
  ASSERT_NE(back.mesh(2), nullptr);
  EXPECT_EQ(back.mesh(2)->bundle, bundle);
  EXPECT_EQ(back.mesh(2)->model, "dir/quad.obj");
  EXPECT_EQ(back.mesh(0), nullptr);
  nlohmann::json j = nlohmann::json::parse(description_json(d));
  j["meshes"][0]["bundle"] = "../../etc-bundle";
  EXPECT_THROW(parse_description(j.dump()), std::invalid_argument);
  j["meshes"][0] = {{"object", -1}, {"bundle", bundle}, {"model", "a.obj"}};
  EXPECT_THROW(parse_description(j.dump()), std::invalid_argument);
  j["meshes"] = "none";
  EXPECT_THROW(parse_description(j.dump()), std::invalid_argument);
}

}  // namespace
}  // namespace lp::server
