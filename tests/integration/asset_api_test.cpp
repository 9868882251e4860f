// Model assets on the real server: a zipped, a tarred and a gzip-tarred OBJ model and a .glb are stored,
// listed, described, deleted and kept across a restart; a scene renders an uploaded OBJ to done and its
// mesh paths stay inside the asset; every refused upload gets its status and code and leaves no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "support/archive_builder.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::ArchiveFormat;
using test::ArchiveMember;
using test::file_member;
using test::folder_member;
using test::MemberType;
using test::Reply;
using namespace std::chrono_literals;

const std::string kObj = "mtllib grid.mtl\nusemtl m\n" + test::grid_obj(4);  // 32 triangles
const std::string kMtl = "newmtl m\nKd 0.8 0.8 0.8\nmap_Kd textures/albedo.png\n";
const std::string kPng = test::checker_png(4);
const std::string kPlainObj = test::grid_obj(4);  // without materials: a model file alone
std::string text_of(const std::filesystem::path& path) {
  const auto bytes = test::read_bytes(path);
  return std::string(bytes.begin(), bytes.end());
}
const std::string kGlb = text_of(test::model_path("quad.glb"));

// An OBJ model with its material and texture, zipped as a folder is zipped.
std::vector<ArchiveMember> textured_obj_in(const std::string& top) {
  return {folder_member(top + "/"), file_member(top + "/grid.obj", kObj),
          file_member(top + "/grid.mtl", kMtl), folder_member(top + "/textures/"),
          file_member(top + "/textures/albedo.png", kPng)};
}

// A server with a state directory of its own, so that tests can look into it.
class AssetServer {
 public:
  explicit AssetServer(std::vector<std::string> flags = {}) {
    flags.insert(flags.end(), {"--state-dir", state_.path().string()});
    server_ = std::make_unique<test::ServerProcess>(flags);
    client_ = server_->client();
  }
  Reply upload(const std::string& name, const std::string& body) const {
    return test::reply(
        client_->Post(("/api/v1/assets?name=" + name).c_str(), body, "application/octet-stream"));
  }
  Reply get(const std::string& path) const { return test::reply(client_->Get(path.c_str())); }
  Reply del(const std::string& path) const { return test::reply(client_->Delete(path.c_str())); }
  Reply render(const std::string& mesh_path) const {
    const json mesh = {{"type", "mesh"}, {"path", mesh_path}, {"transform", {{"translate", {-2, -2, 0}}}}};
    const json camera = {{"position", {0, -8, 4}}, {"look_at", {0, 0, 0}}};
    const json body = {{"envmap", "default"},
                       {"width", 16},
                       {"height", 16},
                       {"spp", 2},
                       {"scene", {{"objects", {mesh}}, {"camera", camera}}}};
    return test::reply(client_->Post("/api/v1/renders", body.dump(), "application/json"));
  }
  json finished_render(const std::string& id) const { return test::finished_render(*client_, id); }
  fs::path assets_dir() const { return state_.path() / "assets"; }
  fs::path files_dir() const { return state_.path() / "asset-files"; }
  const fs::path& state_dir() const { return state_.path(); }
  void stop() {
    client_.reset();
    server_.reset();
  }
  void restart() {
    server_ = std::make_unique<test::ServerProcess>(
        std::vector<std::string>{"--state-dir", state_.path().string()});
    client_ = server_->client();
  }
  bool alive() const { return server_->alive(); }

 private:
  test::TempDir state_;
  std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<httplib::Client> client_;
};

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir)) out.insert(entry.path().filename().string());
  return out;
}

std::string read_text(const fs::path& path) {
  const auto bytes = test::read_bytes(path);
  return {bytes.begin(), bytes.end()};
}

TEST(AssetApi, AZippedModelIsStoredListedDescribedAndDeleted) {
  AssetServer s;
  const Reply created = s.upload("grid", test::make_archive(ArchiveFormat::Zip, textured_obj_in("grid")));
  ASSERT_EQ(created.status, 201) << created.body;
  EXPECT_EQ(created.header("Location"), "/api/v1/assets/grid");
  const json asset = created.body_json();
  EXPECT_EQ(asset["name"], "grid");
  EXPECT_EQ(asset["model"], "grid/grid.obj");
  EXPECT_EQ(asset["format"], "obj");
  EXPECT_EQ(asset["files"], 3);
  EXPECT_EQ(asset["bytes"], kObj.size() + kMtl.size() + kPng.size());
  EXPECT_EQ(asset["path"], "assets/grid");
  EXPECT_EQ(read_text(s.files_dir() / "grid" / "grid" / "textures" / "albedo.png"), kPng);

  EXPECT_EQ(s.get("/api/v1/assets/grid").body_json(), asset);
  EXPECT_EQ(s.get("/api/v1/assets").body_json(), json({{"assets", {asset}}}));

  EXPECT_EQ(s.del("/api/v1/assets/grid").status, 204);
  EXPECT_EQ(s.get("/api/v1/assets/grid").status, 404);
  EXPECT_EQ(s.del("/api/v1/assets/grid").status, 404);
  EXPECT_EQ(s.get("/api/v1/assets").body_json(), json({{"assets", json::array()}}));
  EXPECT_TRUE(names_in(s.assets_dir()).empty());
  EXPECT_TRUE(names_in(s.files_dir()).empty());
}

TEST(AssetApi, TarAndGzipTarWithTheModelAtTheTopLevel) {
  AssetServer s;
  const std::vector<ArchiveMember> members = {file_member("./grid.obj", kObj), file_member("grid.mtl", kMtl),
                                              file_member("textures/albedo.png", kPng)};
  for (const auto& [name, format] :
       {std::pair{"plain_tar", ArchiveFormat::Tar}, {"gzip_tar", ArchiveFormat::TarGz}}) {
    const Reply r = s.upload(name, test::make_archive(format, members));
    ASSERT_EQ(r.status, 201) << name << ": " << r.body;
    EXPECT_EQ(r.body_json()["model"], "grid.obj");
    EXPECT_EQ(r.body_json()["files"], 3);
    EXPECT_EQ(read_text(s.files_dir() / name / "grid.obj"), kObj);
  }
  EXPECT_EQ(s.get("/api/v1/assets").body_json()["assets"].size(), 2u);
}

TEST(AssetApi, AGlbIsKeptAsUploaded) {
  AssetServer s;
  const std::string& glb = kGlb;
  const Reply r = s.upload("box.v2", glb);
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(r.body_json()["model"], "model.glb");
  EXPECT_EQ(r.body_json()["format"], "glb");
  EXPECT_EQ(r.body_json()["files"], 1);
  EXPECT_EQ(r.body_json()["bytes"], glb.size());
  EXPECT_EQ(read_text(s.files_dir() / "box.v2" / "model.glb"), glb);
}

TEST(AssetApi, AssetsAreReloadedAtStartAndLeftoversRemoved) {
  AssetServer s;
  const json zipped =
      s.upload("grid", test::make_archive(ArchiveFormat::Zip, textured_obj_in("grid"))).body_json();
  const json glb = s.upload("box", kGlb).body_json();
  s.stop();
  // What a crash can leave: an unpacked folder renamed into place before its record, and a staged one.
  fs::create_directories(s.files_dir() / "orphan" / "sub");
  fs::create_directories(s.files_dir() / ".tmp-late-1-0" / "sub");
  s.restart();
  EXPECT_EQ(s.get("/api/v1/assets").body_json(), json({{"assets", {glb, zipped}}}));
  EXPECT_EQ(names_in(s.assets_dir()), (std::set<std::string>{"box.json", "grid.json"}));
  EXPECT_EQ(names_in(s.files_dir()), (std::set<std::string>{"box", "grid"}));
  const Reply render = s.render("assets/grid");
  ASSERT_EQ(render.status, 202) << render.body;
  EXPECT_EQ(s.finished_render(render.body_json()["id"])["status"], "done");
}

// A record that cannot be restored keeps its files for the operator, and its name stays taken.
TEST(AssetApi, AnAssetThatCannotBeRestoredKeepsItsFilesAndName) {
  AssetServer s;
  ASSERT_EQ(s.upload("box", kGlb).status, 201);
  s.stop();
  json record = json::parse(read_text(s.assets_dir() / "box.json"));
  record["version"] = 99;  // as a later server might write it
  std::ofstream(s.assets_dir() / "box.json") << record.dump();
  s.restart();
  EXPECT_EQ(s.get("/api/v1/assets").body_json(), json({{"assets", json::array()}}));
  EXPECT_EQ(names_in(s.assets_dir()), (std::set<std::string>{"box.json"}));
  EXPECT_EQ(names_in(s.files_dir()), (std::set<std::string>{"box"}));
  const Reply r = s.upload("box", kGlb);
  EXPECT_EQ(r.status, 409) << r.body;
  EXPECT_NE(r.body.find("could not be restored"), std::string::npos) << r.body;
  EXPECT_EQ(names_in(s.assets_dir()), (std::set<std::string>{"box.json"}));
  EXPECT_EQ(names_in(s.files_dir()), (std::set<std::string>{"box"}));
}

TEST(AssetApi, AnUploadedObjRendersToDone) {
  AssetServer s;
  ASSERT_EQ(s.upload("grid", test::make_archive(ArchiveFormat::Zip, textured_obj_in("grid"))).status, 201);
  for (const std::string path : {"assets/grid", "assets/grid/grid/grid.obj"}) {
    const Reply r = s.render(path);
    ASSERT_EQ(r.status, 202) << path << ": " << r.body;
    const json st = s.finished_render(r.body_json()["id"]);
    EXPECT_EQ(st["status"], "done") << path << ": " << st.dump();
    EXPECT_EQ(st["spp_done"], 2);
  }
}

TEST(AssetApi, AssetMeshPathsStayInsideTheirAsset) {
  AssetServer s;
  ASSERT_EQ(s.upload("grid", test::make_archive(ArchiveFormat::Zip, textured_obj_in("grid"))).status, 201);
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"assets/none", "no asset named 'none'"},
      {"assets/grid/../grid/grid/grid.obj", "'..'"},
      {"assets/grid//etc/passwd", "not absolute"},
      {"assets/grid/grid/missing.obj", "no file 'grid/missing.obj' in the asset 'grid'"},
      {"assets/", "no asset named ''"},
  };
  for (const auto& [path, message] : refused) {
    const Reply r = s.render(path);
    EXPECT_EQ(r.status, 400) << path << ": " << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field") << path;
    EXPECT_NE(r.body.find("scene.objects[0].path"), std::string::npos) << r.body;
    EXPECT_NE(r.body.find(message), std::string::npos) << path << ": " << r.body;
  }
}

struct Refusal {
  std::string label, name, body;
  int status;
  std::string code, message;
};

std::string tar(const std::vector<ArchiveMember>& members) {
  return test::make_archive(ArchiveFormat::Tar, members);
}
std::string zip(const std::vector<ArchiveMember>& members) {
  return test::make_archive(ArchiveFormat::Zip, members);
}

// Each archive also holds a good model, so only the member under test is wrong.
std::vector<Refusal> refusals() {
  const ArchiveMember model = file_member("model.obj", kPlainObj);
  const auto with_model = [&](ArchiveMember m) { return std::vector<ArchiveMember>{model, std::move(m)}; };
  ArchiveMember bomb = file_member("zeros.bin", "");
  bomb.zero_bytes = 4 << 20;
  const std::string cut = tar({model, file_member("more.txt", kObj + kObj)});
  std::vector<ArchiveMember> crowd = {model};
  for (int i = 0; i < 8; ++i) crowd.push_back(file_member("textures/t" + std::to_string(i) + ".png", kPng));
  return {
      {"absolute path (tar)", "a1", tar(with_model(file_member("/etc/evil.obj", "x"))), 400,
       "invalid_argument", "'/etc/evil.obj' has an absolute path"},
      {"absolute path (zip)", "a2", zip(with_model(file_member("/tmp/evil.png", "x"))), 400,
       "invalid_argument", "absolute path"},
      {"'..' (zip)", "d1", zip(with_model(file_member("../evil.png", "x"))), 400, "invalid_argument",
       "'../evil.png' has a '..' component"},
      {"'..' inside (tar)", "d2", tar(with_model(file_member("a/../../evil.png", "x"))), 400,
       "invalid_argument", "'..' component"},
      {"symbolic link (tar)", "l1", tar(with_model({"tex.png", "", MemberType::Symlink, "/etc/passwd"})), 400,
       "invalid_argument", "'tex.png' is a symbolic link"},
      {"symbolic link (zip)", "l2", zip(with_model({"tex.png", "", MemberType::Symlink, "../../x"})), 400,
       "invalid_argument", "is a symbolic link"},
      {"hard link (tar)", "l3", tar(with_model({"copy.obj", "", MemberType::Hardlink, "model.obj"})), 400,
       "invalid_argument", "'copy.obj' is a hard link"},
      {"device (tar)", "v1", tar(with_model({"null", "", MemberType::CharDevice})), 400, "invalid_argument",
       "'null' is a device, FIFO or socket"},
      {"FIFO (tar)", "v2", tar(with_model({"pipe", "", MemberType::Fifo})), 400, "invalid_argument",
       "is a device, FIFO or socket"},
      {"zip bomb", "b1", zip(with_model(bomb)), 413, "too_large",
       "the archive unpacks to more than 1048576 bytes (--max-asset-mb)"},
      {"upload over --max-asset-mb", "b2", test::glb_bytes(std::string(1 << 20, ' ')), 413, "too_large",
       "more than --max-asset-mb allows (1 MiB)"},
      {"too many members", "m1", tar(crowd), 413, "too_large",
       "the archive holds more than 8 members (--max-asset-files)"},
      {"two model files", "t1", zip({model, file_member("other.gltf", "{}")}), 400, "invalid_argument",
       "the archive holds 2 model files: 'model.obj', 'other.gltf'"},
      {"no model file", "n1", zip({file_member("readme.txt", "hi"), file_member("tex.png", kPng)}), 400,
       "invalid_argument", "holds no model file among its 2 files"},
      {"model in nested folders", "n2", zip({file_member("a/b/model.obj", kObj), file_member("c.txt", "")}),
       400, "invalid_argument", "model files lie in nested folders: 'a/b/model.obj'"},
      {"not an archive", "x1", "just some text", 415, "unsupported_media_type",
       "neither a .glb or .gltf model nor a zip"},
      {"truncated .glb", "g1", kGlb.substr(0, kGlb.size() / 2), 422, "invalid_model",
       "glb model.glb: its length is past the end of the file"},
      {"a .gltf that is no JSON", "g2", "{\"asset\": ", 422, "invalid_model", "glTF model.gltf"},
      {"a model without triangles", "g3", test::glb_bytes(R"({"asset":{"version":"2.0"}})"), 422,
       "invalid_model", "glTF model.glb has no triangles in its scene"},
      {"a .glb whose BIN chunk runs 8 bytes past the file", "g5",
       text_of(test::fuzz_corpus_path("gltf", "bin_chunk_past_the_end.glb")), 422, "invalid_model",
       "glb model.glb: chunk 1 at byte 1600: its length 296 runs past the end of the file"},
      {"an archive's broken .obj", "g4", zip({file_member("model.obj", "v 1 2\nf 1 2 3\n")}), 422,
       "invalid_model", "model.obj"},
      {"truncated tar", "x2", cut.substr(0, cut.size() / 2), 422, "corrupt",
       "cannot be read: Truncated tar archive"},
      {"empty body", "e1", "", 400, "empty_body", "empty"},
      {"name starting with '.'", ".hidden", zip({model}), 400, "invalid_field", "field 'name'"},
      {"name too long", std::string(65, 'n'), zip({model}), 400, "invalid_field", "1-64 characters"},
      {"name with '/'", "a%2Fb", zip({model}), 400, "invalid_field", "field 'name'"},
      {"taken name", "taken", zip({model}), 409, "conflict", "an asset named 'taken' exists"},
  };
}

TEST(AssetApi, RefusedUploadsAnswerTheirStatusAndCodeAndLeaveNoFiles) {
  AssetServer s({"--max-asset-mb", "1", "--max-asset-files", "8"});
  ASSERT_EQ(s.upload("taken", zip({file_member("model.obj", kPlainObj)})).status, 201);
  for (const Refusal& refusal : refusals()) {
    const Reply r = s.upload(refusal.name, refusal.body);
    EXPECT_EQ(r.status, refusal.status) << refusal.label << ": " << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], refusal.code) << refusal.label << ": " << r.body;
    EXPECT_NE(r.body.find(refusal.message), std::string::npos) << refusal.label << ": " << r.body;
  }
  EXPECT_EQ(names_in(s.assets_dir()), (std::set<std::string>{"taken.json"}));
  EXPECT_EQ(names_in(s.files_dir()), (std::set<std::string>{"taken"}));
  EXPECT_EQ(s.get("/api/v1/assets").body_json()["assets"].size(), 1u);
  EXPECT_TRUE(s.alive());
}

TEST(AssetApi, TheZipBombIsSmall) {
  const auto all = refusals();
  const auto bomb =
      std::find_if(all.begin(), all.end(), [](const Refusal& r) { return r.label == "zip bomb"; });
  ASSERT_NE(bomb, all.end());
  EXPECT_LT(bomb->body.size(), 16u << 10) << "4 MiB of zeros deflate to a few KiB";
}

TEST(AssetApi, TheNameIsRequired) {
  AssetServer s;
  const Reply r = s.upload("", zip({file_member("model.obj", kObj)}));
  EXPECT_EQ(r.status, 400) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field");
}

// --max-assets counts the assets stored: 507 until one is deleted.
TEST(AssetApi, MaxAssetsCountsTheStoredAssets) {
  AssetServer s({"--max-assets", "1"});
  ASSERT_EQ(s.upload("first", kGlb).status, 201);
  const Reply refused = s.upload("second", kGlb);
  EXPECT_EQ(refused.status, 507) << refused.body;
  EXPECT_EQ(refused.body_json()["error"]["code"], "insufficient_storage");
  EXPECT_NE(refused.body.find("maximum number of assets (--max-assets 1)"), std::string::npos)
      << refused.body;
  EXPECT_EQ(s.del("/api/v1/assets/first").status, 204);
  EXPECT_EQ(s.upload("second", kGlb).status, 201);
}

}  // namespace
}  // namespace lp
