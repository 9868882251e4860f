// Content identity on the real server: two maps that differ in one pixel share no prefiltered chain, no
// SH projection and no content address, while the same pixels under another name do share the chain; an
// interrupted render refuses to resume (409 naming the input) once a model or its map was replaced under
// the same name by other content, and resumes once the same bytes are back.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "support/archive_builder.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/shared_client.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;
using test::Reply;

// A small map with structure; `bright` sets one pixel far above the rest.
Image structured_map(bool bright) {
  Image image(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) image.set(x, y, {0.2f + 0.01f * float(x), 0.3f, 0.5f - 0.01f * float(y)});
  if (bright) image.set(17, 9, {40, 40, 40});
  return image;
}

std::string pfm_of(const Image& image) {
  const auto bytes = write_pfm(image);
  return {bytes.begin(), bytes.end()};
}

Reply upload_map(httplib::Client& client, const std::string& name, const Image& image) {
  return test::reply(
      client.Post(("/api/v1/envmaps?name=" + name).c_str(), pfm_of(image), "application/octet-stream"));
}

Reply prefilter(const std::string& map) {
  const std::string body = R"({"levels":3,"base_size":16,"samples":64,"projection":"octahedral"})";
  return test::reply(test::shared_client().Post(("/api/v1/envmaps/" + map + "/prefilter").c_str(), body,
                                                "application/json"));
}

// The chain's one KTX2 file, once the job is done.
std::string chain_file(const Reply& submitted) {
  const json done = test::finished_job(test::shared_client(), submitted.header("Location"));
  EXPECT_EQ(done["status"], "done") << done;
  return done["status"] == "done" ? test::shared_get(done["files"][0]["url"]).body : "";
}

Image fetched_content(const std::string& hash) {
  const Reply r = test::shared_get("/api/v1/content/" + hash);
  EXPECT_EQ(r.status, 200) << hash << ": " << r.body;
  if (r.status != 200) return {};
  return read_image({reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()}).image;
}

bool same_pixels(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::equal(a.data().begin(), a.data().end(), b.data().begin());
}

TEST(ContentIdentity, MapsDifferingInOnePixelNeverShareAResult) {
  auto& client = test::shared_client();
  const Image plain = structured_map(false), one_pixel_other = structured_map(true);
  ASSERT_EQ(upload_map(client, "identity_plain", plain).status, 201);
  ASSERT_EQ(upload_map(client, "identity_plain_again", plain).status, 201);
  ASSERT_EQ(upload_map(client, "identity_one_pixel", one_pixel_other).status, 201);

  const Reply first = prefilter("identity_plain");
  ASSERT_EQ(first.status, 202) << first.body;
  EXPECT_EQ(first.body_json()["reused"], false);
  const std::string plain_chain = chain_file(first);
  // The same pixels under another name: the same chain.
  const Reply again = prefilter("identity_plain_again");
  EXPECT_EQ(again.status, 200) << again.body;
  EXPECT_EQ(again.body_json()["reused"], true);
  EXPECT_EQ(again.header("Location"), first.header("Location"));
  // One pixel other: a chain of its own, and another one.
  const Reply other = prefilter("identity_one_pixel");
  ASSERT_EQ(other.status, 202) << other.body;
  EXPECT_EQ(other.body_json()["reused"], false);
  EXPECT_NE(other.header("Location"), first.header("Location"));
  EXPECT_NE(chain_file(other), plain_chain);

  const json sh_plain = test::shared_get("/api/v1/envmaps/identity_plain/sh").body_json();
  const json sh_other = test::shared_get("/api/v1/envmaps/identity_one_pixel/sh").body_json();
  ASSERT_TRUE(sh_plain.contains("radiance")) << sh_plain;
  EXPECT_NE(sh_plain["radiance"], sh_other["radiance"]);

  // Content addresses: 64 hex digits of SHA-256, each answering its own pixels.
  const std::string plain_hash = server::envmap_content_hash(EnvMap(structured_map(false)));
  const std::string other_hash = server::envmap_content_hash(EnvMap(structured_map(true)));
  EXPECT_NE(plain_hash, other_hash);
  EXPECT_TRUE(same_pixels(fetched_content(plain_hash), plain));
  EXPECT_TRUE(same_pixels(fetched_content(other_hash), one_pixel_other));
  EXPECT_EQ(test::shared_get("/api/v1/content/" + plain_hash.substr(48)).status, 404);  // a 64-bit prefix
}

// A quad, and the same quad with one corner raised by a millimetre.
std::string quad_obj(bool raised) {
  return std::string("v -1 -1 0\nv 1 -1 0\nv 1 1 ") + (raised ? "0.001" : "0") +
         "\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
}

std::string asset_zip(bool raised) {
  return test::make_archive(test::ArchiveFormat::Zip, {test::file_member("model.obj", quad_obj(raised))});
}

class StatefulServer {
 public:
  explicit StatefulServer(const test::TempDir& state)
      : server_({"--state-dir", state.path().string()}), client_(server_.client()) {}
  test::ServerProcess& process() { return server_; }
  Reply post(const std::string& path, const std::string& body, const std::string& type) const {
    return test::reply(client_->Post(path.c_str(), body, type));
  }
  Reply get(const std::string& path) const { return test::reply(client_->Get(path.c_str())); }
  Reply del(const std::string& path) const { return test::reply(client_->Delete(path.c_str())); }
  Reply replace_asset(const std::string& name, const std::string& zip) const {
    EXPECT_EQ(del("/api/v1/assets/" + name).status, 204);
    return post("/api/v1/assets?name=" + name, zip, "application/octet-stream");
  }
  Reply replace_map(const std::string& name, const Image& image) const {
    EXPECT_EQ(del("/api/v1/envmaps/" + name).status, 204);
    return upload_map(*client_, name, image);
  }
  Reply resume(const std::string& id) const {
    return post("/api/v1/renders/" + id + "/resume", "", "application/json");
  }

 private:
  test::ServerProcess server_;
  std::unique_ptr<httplib::Client> client_;
};

TEST(ContentIdentity, AResumeRefusesAReplacedModelOrMapNamingIt) {
  test::TempDir state;
  std::string id;
  {
    StatefulServer server(state);
    ASSERT_EQ(server.post("/api/v1/assets?name=quad", asset_zip(false), "application/octet-stream").status,
              201);
    ASSERT_EQ(upload_map(*server.process().client(), "sky", structured_map(false)).status, 201);
    const json mesh = {{"type", "mesh"}, {"path", "assets/quad"}};
    const json body = {{"envmap", "sky"}, {"width", 64}, {"height", 64},
                       {"spp", 8192},     {"seed", 5},   {"scene", {{"objects", {mesh}}}}};
    const Reply submitted = server.post("/api/v1/renders", body.dump(), "application/json");
    ASSERT_EQ(submitted.status, 202) << submitted.body;
    id = submitted.body_json()["id"];
    json st;
    do {
      std::this_thread::sleep_for(10ms);
      st = server.get("/api/v1/renders/" + id).body_json();
    } while (st["spp_done"].get<int>() < 2 && !test::job_ended(st));
    ASSERT_FALSE(test::job_ended(st)) << st;
    server.process().send_signal(SIGKILL);
    EXPECT_EQ(server.process().wait_exit(30s), -SIGKILL);
  }

  StatefulServer server(state);
  const json interrupted = server.get("/api/v1/renders/" + id).body_json();
  ASSERT_EQ(interrupted["status"], "interrupted") << interrupted;
  ASSERT_GT(interrupted["spp_done"].get<int>(), 0);

  ASSERT_EQ(server.replace_asset("quad", asset_zip(true)).status, 201);
  const Reply model_changed = server.resume(id);
  EXPECT_EQ(model_changed.status, 409) << model_changed.body;
  EXPECT_EQ(model_changed.body_json()["error"]["code"], "model_changed") << model_changed.body;
  EXPECT_NE(model_changed.body.find("'assets/quad' (scene.objects[0].path)"), std::string::npos)
      << model_changed.body;

  ASSERT_EQ(server.replace_asset("quad", asset_zip(false)).status, 201);  // the same bytes, written again
  ASSERT_EQ(server.replace_map("sky", structured_map(true)).status, 201);
  const Reply map_changed = server.resume(id);
  EXPECT_EQ(map_changed.status, 409) << map_changed.body;
  EXPECT_EQ(map_changed.body_json()["error"]["code"], "envmap_changed") << map_changed.body;
  EXPECT_NE(map_changed.body.find("'sky'"), std::string::npos) << map_changed.body;

  ASSERT_EQ(server.replace_map("sky", structured_map(false)).status, 201);
  const Reply resumed = server.resume(id);
  EXPECT_EQ(resumed.status, 202) << resumed.body;
  EXPECT_EQ(server.del("/api/v1/renders/" + id).status, 202);
}

}  // namespace
}  // namespace lp
