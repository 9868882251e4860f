// Renders with `denoise` through the real server and its real denoiser: the denoised colour of a 4 spp
// render of the `materials` preset is nearer a 1024 spp render than the raw colour is; the status names it;
// pass=denoised is refused until it is ready and for a render that did not ask; a cancel stops the
// denoise; it survives a restart, and an interrupted render is denoised once resumed;
// turntables denoise by default; and a server without the weights refuses a denoise with 503.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/image_error.hpp"
#include "support/poll_until.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

constexpr int kWidth = 96, kHeight = 64;

// A server keeping its state in its own folder, restartable over it, with the forest map loaded.
class DenoiseServer {
 public:
  DenoiseServer() { start(); }
  void restart() {
    client_.reset();
    server_.reset();
    start();
  }
  Reply get(const std::string& path) const { return test::reply(client_->Get(path.c_str())); }
  Reply post(const std::string& path, const json& body) const {
    return test::reply(client_->Post(path.c_str(), body.dump(), "application/json"));
  }
  Reply del(const std::string& path) const { return test::reply(client_->Delete(path.c_str())); }
  json status(const std::string& id) const { return get("/api/v1/renders/" + id).body_json(); }
  // Submits and waits for the render to end; its id.
  std::string rendered(const json& body) const {
    const Reply r = post("/api/v1/renders", body);
    EXPECT_EQ(r.status, 202) << r.body;
    const std::string id = r.body_json().value("id", "");
    EXPECT_EQ(test::finished_render(*client_, id)["status"], "done");
    return id;
  }
  Image image(const std::string& id, const std::string& pass) const {
    const Reply r = get("/api/v1/renders/" + id + "/image?format=pfm&pass=" + pass);
    EXPECT_EQ(r.status, 200) << r.body;
    return read_image({reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()}).image;
  }
  // Polls the render's status until `done` holds.
  template <class Pred>
  json status_when(const std::string& id, Pred&& done) const {
    return test::poll_until(
        "render " + id, [&] { return status(id); }, done);
  }

 private:
  void start() {
    server_ = std::make_unique<test::ServerProcess>(
        std::vector<std::string>{"--state-dir", state_.path().string(), "--load",
                                 "forest=" + test::envmap_path("forest.exr").string()});
    client_ = server_->client();
  }
  test::TempDir state_;
  std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<httplib::Client> client_;
};

DenoiseServer& server() {
  static DenoiseServer s;
  return s;
}

json materials(int spp, json extra = json::object()) {
  json body = {{"envmap", "forest"}, {"width", kWidth}, {"height", kHeight},
               {"spp", spp},         {"seed", 7},       {"scene", {{"preset", "materials"}}}};
  body.update(extra);
  return body;
}

TEST(RenderDenoiseApi, TheDenoisedColourIsNearerAConvergedRenderThanTheRawOne) {
  const DenoiseServer& s = server();
  const std::string reference_id = s.rendered(materials(1024));
  const std::string id = s.rendered(materials(4, {{"denoise", true}}));
  const json st = s.status(id);
  EXPECT_EQ(st["denoise"], true);
  EXPECT_EQ(st["denoised"]["ready"], true);
  EXPECT_GT(st["denoised"]["seconds"].get<double>(), 0.0);
  EXPECT_EQ(st["passes"], json::array({"albedo", "normal"}));  // implied by denoise
  EXPECT_EQ(st["progress"], 1.0);

  const Image reference = s.image(reference_id, "color");
  const Image raw = s.image(id, "color");  // the raw colour stays the default picture
  const Image denoised = s.image(id, "denoised");
  ASSERT_EQ(denoised.width(), kWidth);
  ASSERT_EQ(denoised.height(), kHeight);
  const double raw_error = test::rel_mse(raw, reference), denoised_error = test::rel_mse(denoised, reference);
  std::cout << "materials at 4 spp against 1024 spp: relMSE raw " << raw_error << ", denoised "
            << denoised_error << "\n";
  EXPECT_LT(denoised_error, 0.25 * raw_error);

  // Every picture format of the colour, and the denoised colour among pass=all's channels.
  for (const char* format : {"png", "jpeg", "webp", "exr"})
    EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?pass=denoised&format=" + format).status, 200) << format;
  const Reply all = s.get("/api/v1/renders/" + id + "/image?pass=all&format=exr");
  EXPECT_EQ(all.status, 200);
  EXPECT_NE(all.body.find("Denoised.R"), std::string::npos);
}

TEST(RenderDenoiseApi, PassDenoisedIsRefusedWhenNotAskedForAndUntilReady) {
  const DenoiseServer& s = server();
  const std::string plain = s.rendered(materials(1));
  EXPECT_EQ(s.status(plain)["denoise"], false);
  EXPECT_TRUE(s.status(plain)["denoised"].is_null());
  const Reply not_asked = s.get("/api/v1/renders/" + plain + "/image?pass=denoised");
  EXPECT_EQ(not_asked.status, 409);
  EXPECT_EQ(not_asked.body_json()["error"]["code"], "pass_not_rendered");
  EXPECT_NE(not_asked.body.find("did not ask for"), std::string::npos) << not_asked.body;

  // A long render with denoise: its image exists after the first pass, its denoised colour does not.
  const Reply r = s.post("/api/v1/renders", materials(65536, {{"denoise", true}}));
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string id = r.body_json()["id"];
  s.status_when(id, [](const json& st) { return st["image_available"] == true; });
  EXPECT_EQ(s.status(id)["denoised"], (json{{"ready", false}, {"seconds", nullptr}}));
  const Reply early = s.get("/api/v1/renders/" + id + "/image?pass=denoised");
  EXPECT_EQ(early.status, 409);
  EXPECT_EQ(early.body_json()["error"]["code"], "pass_not_rendered");
  EXPECT_NE(early.body.find("not ready"), std::string::npos) << early.body;
  // Cancelled before its last sample, it never has one.
  EXPECT_EQ(s.del("/api/v1/renders/" + id).status, 202);
  EXPECT_EQ(s.status_when(id, test::job_ended)["status"], "cancelled");
  EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?pass=denoised").status, 409);
  EXPECT_EQ(s.status(id)["denoised"]["ready"], false);
}

// The denoise is the last tenth of the progress; a cancel stops it there, and the render has no denoised
// colour.
TEST(RenderDenoiseApi, ACancelStopsTheDenoise) {
  const DenoiseServer& s = server();
  const Reply r =
      s.post("/api/v1/renders", materials(1, {{"denoise", true}, {"width", 1536}, {"height", 1024}}));
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string id = r.body_json()["id"];
  // Every sample done and the job still running: the denoise has its turn.
  const json denoising =
      s.status_when(id, [](const json& st) { return test::job_ended(st) || st["spp_done"] == 1; });
  ASSERT_EQ(denoising["status"], "running") << "the denoise of 1536x1024 ended before it was seen";
  EXPECT_GE(denoising["progress"].get<double>(), 0.89);
  EXPECT_EQ(s.del("/api/v1/renders/" + id).status, 202);
  const json ended = s.status_when(id, test::job_ended);
  EXPECT_EQ(ended["status"], "cancelled");
  EXPECT_EQ(ended["denoised"]["ready"], false);
  EXPECT_LT(ended["progress"].get<double>(), 1.0);
  EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?pass=denoised").status, 409);
  EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?format=pfm").status, 200);  // the raw colour stays
}

TEST(RenderDenoiseApi, TheDenoisedColourSurvivesARestart) {
  DenoiseServer& s = server();
  const std::string id = s.rendered(materials(2, {{"denoise", true}, {"width", 48}, {"height", 32}}));
  const json before = s.status(id);
  const std::string path = "/api/v1/renders/" + id + "/image?format=exr&pass=denoised";
  const Reply denoised = s.get(path);
  ASSERT_EQ(denoised.status, 200);
  s.restart();
  const json after = s.status(id);
  EXPECT_EQ(after["status"], "done");
  EXPECT_EQ(after["denoised"], before["denoised"]);
  const Reply again = s.get(path);
  EXPECT_EQ(again.status, 200);
  EXPECT_TRUE(again.body == denoised.body) << "the denoised image differs after a restart";
}

// A render a stop interrupted has no denoised colour; resumed, it finishes its samples and denoises them.
TEST(RenderDenoiseApi, AnInterruptedRenderIsDenoisedWhenResumed) {
  DenoiseServer& s = server();
  const Reply r =
      s.post("/api/v1/renders", materials(512, {{"denoise", true}, {"width", 48}, {"height", 32}}));
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string id = r.body_json()["id"];
  s.status_when(id, [](const json& st) { return test::job_ended(st) || st["spp_done"].get<int>() > 0; });
  s.restart();  // SIGTERM: the running pass ends, the render is interrupted
  const json interrupted = s.status(id);
  ASSERT_EQ(interrupted["status"], "interrupted") << interrupted.dump();
  EXPECT_EQ(interrupted["denoised"]["ready"], false);
  EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?pass=denoised").status, 409);
  const Reply resumed = s.post("/api/v1/renders/" + id + "/resume", json::object());
  ASSERT_EQ(resumed.status, 202) << resumed.body;
  const json done = s.status_when(id, test::job_ended);
  EXPECT_EQ(done["status"], "done");
  EXPECT_EQ(done["spp_done"], 512);
  EXPECT_EQ(done["denoised"]["ready"], true);
  EXPECT_EQ(s.get("/api/v1/renders/" + id + "/image?pass=denoised").status, 200);
}

TEST(RenderDenoiseApi, TurntablesDenoiseByDefault) {
  const DenoiseServer& s = server();
  json body = materials(2, {{"width", 32}, {"height", 32}, {"turntable", {{"frames", 2}}}});
  for (const bool denoise : {true, false}) {
    if (!denoise) body["denoise"] = false;
    const Reply r = s.post("/api/v1/turntables", body);
    ASSERT_EQ(r.status, 202) << r.body;
    EXPECT_EQ(r.body_json()["denoise"], denoise);
    const std::string url = "/api/v1/turntables/" + r.body_json()["id"].get<std::string>();
    EXPECT_EQ(test::poll_until(
                  url, [&] { return s.get(url).body_json(); }, test::job_ended)["status"],
              "done");
  }
}

TEST(RenderDenoiseApi, AServerWithoutTheWeightsRefusesADenoise) {
  test::TempDir empty;
  test::ServerProcess s({"--denoise-weights", empty.path().string()});
  const auto client = s.client();
  EXPECT_EQ(test::reply(client->Get("/api/v1/health")).body_json()["denoiser"]["available"], false);
  const auto post = [&](const std::string& path, const json& body) {
    return test::reply(client->Post(path.c_str(), body.dump(), "application/json"));
  };
  const json render = {{"envmap", "default"}, {"width", 8}, {"height", 8}, {"spp", 1}};
  json denoised = render;
  denoised["denoise"] = true;
  const Reply refused = post("/api/v1/renders", denoised);
  EXPECT_EQ(refused.status, 503) << refused.body;
  EXPECT_EQ(refused.body_json()["error"]["code"], "denoiser_unavailable");
  EXPECT_EQ(post("/api/v1/renders", render).status, 202);
  json turntable = render;
  turntable["turntable"] = {{"frames", 1}};
  EXPECT_EQ(post("/api/v1/turntables", turntable).body_json()["error"]["code"], "denoiser_unavailable");
  turntable["denoise"] = false;
  EXPECT_EQ(post("/api/v1/turntables", turntable).status, 202);
  EXPECT_EQ(test::reply(client->Get("/api/v1/health")).body_json()["denoiser"]["available"], false);
}

}  // namespace
}  // namespace lp
