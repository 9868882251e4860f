// Every limit flag a request can exceed (server::int_flag_parameters() with an `exceeded` code) is enforced
// by the real server: one server runs with each such flag set low, and a request just over each limit gets
// the declared 4xx with a message naming what was over. A new limit flag without a probe here fails the test.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "api/parameters.hpp"
#include "server/options.hpp"
#include "support/archive_builder.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

// The low value of each limit flag, and a request just over it: an upload of a map (a file of
// tests/data/envmaps, or `map` bytes named `named`) or of a model asset, or a JSON body posted to `path`;
// `named` is a part of the error message.
struct Probe {
  std::string value;
  std::string path;  // empty: upload `file`, or `asset` if it is not empty
  json body;
  std::string named;
  std::string file = "";
  std::string asset = "";
  std::vector<uint8_t> map = {};
};

Reply send(httplib::Client& c, const Probe& p) {
  if (!p.path.empty()) return test::reply(c.Post(p.path.c_str(), p.body.dump(), "application/json"));
  if (!p.asset.empty())
    return test::reply(
        c.Post(("/api/v1/assets?name=" + p.named).c_str(), p.asset, "application/octet-stream"));
  const std::vector<uint8_t> bytes = p.map.empty() ? test::read_bytes(test::envmap_path(p.file)) : p.map;
  std::string name = p.map.empty() ? p.file : p.named;
  if (p.map.empty()) name[name.find('.')] = '_';
  return test::reply(c.Post(("/api/v1/envmaps?name=" + name).c_str(),
                            reinterpret_cast<const char*>(bytes.data()), bytes.size(),
                            "application/octet-stream"));
}

Probe render(const std::string& value, json fields, const std::string& named) {
  fields["envmap"] = "default";
  fields["width"] = fields.value("width", 8);
  fields["height"] = fields.value("height", 8);
  fields["spp"] = fields.value("spp", 1);
  return {value, "/api/v1/renders", fields, named};
}

// A tar of a model and two more files: three members.
std::string three_member_archive() {
  return test::make_archive(test::ArchiveFormat::Tar, {test::file_member("model.obj", test::grid_obj(1)),
                                                       test::file_member("model.mtl", "newmtl m\n"),
                                                       test::file_member("albedo.png", "png")});
}

// A zip of a few KiB that unpacks to a model and 1.5 MiB of zeros (the upload stays under --max-upload-mb 1).
std::string zip_unpacking_to_1_5_mib() {
  test::ArchiveMember zeros = test::file_member("zeros.bin", "");
  zeros.zero_bytes = 3 << 19;
  return test::make_archive(test::ArchiveFormat::Zip,
                            {test::file_member("model.obj", test::grid_obj(1)), zeros});
}

json textured(const std::string& folder) {
  return {{"type", "mesh"}, {"path", folder + "/quad.obj"}};
}

std::map<std::string, Probe> probes() {
  const json sphere = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}};
  const json mesh = {{"type", "mesh"}, {"path", "grid.obj"}};
  return {
      {"max-upload-mb", {"1", "", {}, "large", "", "", test::grey_map_pfm(512, 256)}},  // 1.5 MiB
      {"max-pixels", {"1000", "", {}, "1000", "forest.exr"}},
      {"max-samples", {"100", "/api/v1/envmaps/default/samples", {{"count", 101}}, "count"}},
      {"max-lights", {"16", "/api/v1/envmaps/default/median-cut", {{"count", 17}}, "count"}},
      {"max-render-width", render("32", {{"width", 33}}, "'width'")},
      {"max-render-height", render("24", {{"height", 25}}, "'height'")},
      {"max-render-spp", render("4", {{"spp", 5}}, "'spp'")},
      {"max-render-depth", render("2", {{"max_depth", 3}}, "'max_depth'")},
      {"max-render-objects", render("1", {{"scene", {{"objects", {sphere, sphere}}}}}, "scene.objects")},
      {"max-mesh-triangles", render("10", {{"scene", {{"objects", {mesh}}}}}, "scene.objects[0].path")},
      {"max-texture-pixels", render("16", {{"scene", {{"objects", {textured("large")}}}}},
                                    "over the limit of 16 pixels per texture")},
      {"max-model-texture-pixels",
       render("24", {{"scene", {{"objects", {textured("two")}}}}}, "over 24 pixels together")},
      {"max-asset-mb", {"1", "", {}, "max-asset-mb", "", zip_unpacking_to_1_5_mib()}},
      {"max-asset-files", {"2", "", {}, "max-asset-files", "", three_member_archive()}},
  };
}

// A data directory holding grid.obj (32 triangles) and two textured quads: large/quad.obj with a texture
// of 5 x 4 pixels, two/quad.obj with two textures of 4 x 4 pixels.
struct DataDir {
  test::TempDir dir;
  DataDir() {
    std::ofstream(dir.path() / "grid.obj") << test::grid_obj(4);
    for (const char* folder : {"large", "two"}) std::filesystem::create_directory(dir.path() / folder);
    test::write_textured_quad(dir.path() / "large", test::solid_png(5, 4, {200, 200, 200}));
    test::write_textured_quad(dir.path() / "two", test::solid_png(4, 4, {200, 200, 200}),
                              test::solid_png(4, 4, {128, 128, 255}));
  }
  std::string path() const { return dir.path().string(); }
};

TEST(LimitFlags, EveryLimitARequestCanExceedAnswersItsDeclaredStatus) {
  const auto all = probes();
  const DataDir data;
  std::vector<std::string> flags = {"--data-dir", data.path()};
  std::vector<const api::IntParameter*> limits;
  for (const api::IntParameter* p : server::int_flag_parameters()) {
    if (!p->exceeded) continue;
    const auto probe = all.find(p->flag);
    ASSERT_NE(probe, all.end()) << "--" << p->flag << " has no probe in this test";
    limits.push_back(p);
    flags.insert(flags.end(), {std::string("--") + p->flag, probe->second.value});
  }
  EXPECT_EQ(limits.size(), all.size()) << "a probe for a flag that declares no exceeded code";
  test::ServerProcess server(flags);
  auto client = server.client();
  for (const api::IntParameter* p : limits) {
    const Probe& probe = all.at(p->flag);
    const Reply r = send(*client, probe);
    EXPECT_EQ(r.status, api::http_status(*p->exceeded)) << "--" << p->flag << ": " << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], api::code_name(*p->exceeded))
        << "--" << p->flag << ": " << r.body;
    EXPECT_NE(r.body.find(probe.named), std::string::npos) << "--" << p->flag << ": " << r.body;
  }
  EXPECT_TRUE(server.alive());
}

// The same requests are accepted under the default limits (so each probe exceeds only its flag).
TEST(LimitFlags, TheProbesPassUnderTheDefaultLimits) {
  const DataDir data;
  test::ServerProcess server({"--data-dir", data.path()});
  auto client = server.client();
  for (const auto& [flag, probe] : probes()) {
    const Reply r = send(*client, probe);
    EXPECT_TRUE(r.status == 200 || r.status == 201 || r.status == 202)
        << "--" << flag << ": " << r.status << " " << r.body;
  }
}

// --max-envmaps counts the maps held, the built-in one included: 507 until one is deleted.
TEST(LimitFlags, MaxEnvmapsCountsTheMapsHeld) {
  test::ServerProcess server({"--max-envmaps", "1"});
  auto client = server.client();
  const Probe upload{"", "", {}, "", "forest.pfm"};
  const Reply refused = send(*client, upload);
  EXPECT_EQ(refused.status, 507) << refused.body;
  EXPECT_NE(refused.body.find("maximum number of maps (1)"), std::string::npos) << refused.body;
  EXPECT_EQ(test::reply(client->Delete("/api/v1/envmaps/default")).status, 204);
  EXPECT_EQ(send(*client, upload).status, 201);
}

// api/openapi.yaml names the flags by which the server limits requests: every limit a request can
// exceed is named there, and every flag named there is one the server takes (its --help lists it).
TEST(LimitFlags, TheOpenApiDocumentNamesEveryRequestLimitAndOnlyRealFlags) {
  std::ifstream in(LIGHTPROBE_OPENAPI);
  const std::string document{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(document.size(), 1000u);
  for (const api::IntParameter* p : server::int_flag_parameters()) {
    if (!p->exceeded) continue;
    EXPECT_NE(document.find(std::string("--") + p->flag), std::string::npos)
        << "--" << p->flag << " is not named in api/openapi.yaml";
  }
  const test::StartFailure help = test::run_until_exit({"--help"}, std::chrono::seconds(10));
  ASSERT_EQ(help.exit_status, 0) << help.output;
  const std::regex flag(R"(--[a-z][a-z0-9-]*[a-z0-9])");
  for (auto it = std::sregex_iterator(document.begin(), document.end(), flag); it != std::sregex_iterator();
       ++it)
    EXPECT_TRUE(std::regex_search(help.output, std::regex("  " + it->str() + "\\b")))
        << it->str() << " is named in api/openapi.yaml but is not a flag of the server";
}

}  // namespace
}  // namespace lp
