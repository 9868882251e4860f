// Turntables on the real server: a 4-frame turntable of a glTF model finishes with its cameras a quarter
// turn apart, frames that differ, a zip of 4 PNGs and cameras.json, a 4-frame animated WebP and a contact
// sheet of the right size; a cancel stops one mid-way; bad fields are 400s naming the field. And
// thumbnails of a render's image: size= gives JPEG and WebP of the fitted size, with a working ETag.
#include <archive.h>
#include <archive_entry.h>
#include <gtest/gtest.h>
#include <stb_image.h>
#include <webp/decode.h>
#include <webp/demux.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/poll_until.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

// The test data as --data-dir (models/quad.glb), the forest map, and frames of at most 600000 pixels
// together.
test::ServerProcess& server() {
  static test::ServerProcess s(
      {"--data-dir", test::model_path("quad.glb").parent_path().parent_path().string(), "--load",
       "forest=" + test::envmap_path("forest.exr").string(), "--max-pixels", "600000"});
  return s;
}

Reply get(const std::string& path, const httplib::Headers& headers = {}) {
  return test::reply(server().client()->Get(path.c_str(), headers));
}
Reply post(const std::string& path, const json& body) {
  return test::reply(server().client()->Post(path.c_str(), body.dump(), "application/json"));
}

json turntable_body(int frames, int size, int spp) {
  return {{"envmap", "forest"}, {"scene", {{"objects", {{{"type", "mesh"}, {"path", "models/quad.glb"}}}}}},
          {"width", size},      {"height", size},
          {"spp", spp},         {"turntable", {{"frames", frames}, {"elevation_deg", 30}}}};
}

using Decoded = test::PngPixels;
// A PNG or JPEG answer decoded to 8-bit RGB (stb_image reads both).
Decoded decode_stb(const std::string& bytes) {
  return test::decode_png({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()});
}

// The members of a zip, read with libarchive.
std::map<std::string, std::string> unzip(const std::string& bytes) {
  std::map<std::string, std::string> members;
  archive* a = archive_read_new();
  archive_read_support_format_zip(a);
  EXPECT_EQ(archive_read_open_memory(a, bytes.data(), bytes.size()), ARCHIVE_OK);
  archive_entry* entry = nullptr;
  while (archive_read_next_header(a, &entry) == ARCHIVE_OK) {
    std::string content(size_t(archive_entry_size(entry)), '\0');
    EXPECT_EQ(archive_read_data(a, content.data(), content.size()), la_ssize_t(content.size()));
    members[archive_entry_pathname(entry)] = content;
  }
  archive_read_free(a);
  return members;
}

// The azimuth of a camera about its target, as CameraFit counts it: 0 from -y, 90 from +x.
double azimuth_deg(const json& camera) {
  const double dx = camera["position"][0].get<double>() - camera["look_at"][0].get<double>();
  const double dy = camera["position"][1].get<double>() - camera["look_at"][1].get<double>();
  return std::atan2(dx, -dy) * 180.0 / M_PI;
}

// The mean absolute difference of two pictures' bytes, in 8-bit steps.
double mean_difference(const Decoded& a, const Decoded& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
  return sum / double(a.rgb.size());
}

const json& finished_turntable() {
  static const json status = [] {
    const Reply r = post("/api/v1/turntables", turntable_body(4, 32, 4));
    EXPECT_EQ(r.status, 202) << r.body;
    EXPECT_EQ(r.header("Location"), "/api/v1/turntables/" + r.body_json()["id"].get<std::string>());
    return test::finished_job(*server().client(), r.header("Location"));
  }();
  return status;
}
std::string turntable_url() {
  return "/api/v1/turntables/" + finished_turntable()["id"].get<std::string>();
}

TEST(TurntableApi, FourFramesFinishWithCamerasAQuarterTurnApart) {
  const json& st = finished_turntable();
  ASSERT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["frames"], 4);
  EXPECT_EQ(st["frames_done"], 4);
  EXPECT_DOUBLE_EQ(st["progress"].get<double>(), 1.0);
  ASSERT_EQ(st["cameras"].size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const json& c = st["cameras"][size_t(i)];
    EXPECT_EQ(c["index"], i);
    const double expected = std::remainder(90.0 * i, 360.0);
    EXPECT_NEAR(std::remainder(azimuth_deg(c) - expected, 360.0), 0.0, 1e-3) << c.dump();
    for (int k = 0; k < 3; ++k)  // the matrix's translation is the position
      EXPECT_NEAR(c["matrix"][size_t(4 * k + 3)].get<double>(), c["position"][size_t(k)].get<double>(), 1e-5);
  }
}

TEST(TurntableApi, FramesDiffer) {
  const Decoded first = decode_stb(get(turntable_url() + "/frames/0").body);
  const Decoded second = decode_stb(get(turntable_url() + "/frames/1").body);
  ASSERT_EQ(first.width, 32);
  ASSERT_EQ(second.width, 32);
  EXPECT_GT(mean_difference(first, second), 1.0);  // the quad seen from another side
  EXPECT_EQ(get(turntable_url() + "/frames/4").status, 404);
  EXPECT_EQ(get(turntable_url() + "/frames/x").status, 404);
}

TEST(TurntableApi, ZipHoldsFourPngsAndTheCameras) {
  const Reply r = get(turntable_url() + "/frames.zip");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type(), "application/zip");
  const auto members = unzip(r.body);
  ASSERT_EQ(members.size(), 5u);
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png", "frame_0003.png"}) {
    ASSERT_TRUE(members.count(name)) << name;
    const Decoded frame = decode_stb(members.at(name));
    EXPECT_EQ(frame.width, 32) << name;
    EXPECT_EQ(frame.height, 32) << name;
  }
  ASSERT_TRUE(members.count("cameras.json"));
  EXPECT_EQ(json::parse(members.at("cameras.json")), finished_turntable()["cameras"]);
  // The zip's frames are the frames the route gives, tone mapped alike.
  EXPECT_EQ(decode_stb(members.at("frame_0002.png")).rgb,
            decode_stb(get(turntable_url() + "/frames/2").body).rgb);
}

TEST(TurntableApi, AnimationIsAFourFrameWebp) {
  const Reply r = get(turntable_url() + "/animation.webp?fps=4&size=16");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type(), "image/webp");
  WebPData data{reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()};
  WebPAnimDecoderOptions options;
  ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  ASSERT_NE(decoder, nullptr);
  WebPAnimInfo info;
  ASSERT_TRUE(WebPAnimDecoderGetInfo(decoder, &info));
  EXPECT_EQ(info.frame_count, 4u);
  EXPECT_EQ(info.canvas_width, 16u);
  EXPECT_EQ(info.canvas_height, 16u);
  int frames = 0, last_ms = 0;
  while (WebPAnimDecoderHasMoreFrames(decoder)) {
    uint8_t* pixels = nullptr;
    ASSERT_TRUE(WebPAnimDecoderGetNext(decoder, &pixels, &last_ms));
    ++frames;
  }
  EXPECT_EQ(frames, 4);
  EXPECT_EQ(last_ms, 4 * 250);  // 4 fps: each frame 250 ms
  WebPAnimDecoderDelete(decoder);
}

TEST(TurntableApi, ContactSheetTilesTheFramesTwoByTwo) {
  const Decoded sheet = decode_stb(get(turntable_url() + "/contact-sheet").body);
  EXPECT_EQ(sheet.width, 64);
  EXPECT_EQ(sheet.height, 64);
  // Its bottom-left cell is frame 2 (row 1, column 0).
  const Decoded frame = decode_stb(get(turntable_url() + "/frames/2").body);
  ASSERT_EQ(frame.width, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32 * 3; ++x)
      ASSERT_EQ(sheet.rgb[size_t((32 + y) * 64 * 3 + x)], frame.rgb[size_t(y * 32 * 3 + x)]) << x << "," << y;
  const Reply small = get(turntable_url() + "/contact-sheet?format=jpeg&size=40");
  EXPECT_EQ(small.type(), "image/jpeg");
  const Decoded jpeg = decode_stb(small.body);
  EXPECT_EQ(jpeg.width, 40);
  EXPECT_EQ(jpeg.height, 40);
}

// The RGBA pixels of the first frame of an animated WebP (libwebp's demuxer); empty if it cannot decode.
std::vector<uint8_t> first_webp_frame(const std::string& bytes, int& width) {
  WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options)) return {};
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  if (!decoder) return {};
  WebPAnimInfo info;
  uint8_t* pixels = nullptr;
  int ms = 0;
  std::vector<uint8_t> out;
  if (WebPAnimDecoderGetInfo(decoder, &info) && WebPAnimDecoderGetNext(decoder, &pixels, &ms)) {
    width = int(info.canvas_width);
    out.assign(pixels, pixels + size_t(info.canvas_width) * info.canvas_height * 4);
  }
  WebPAnimDecoderDelete(decoder);
  return out;
}

// A turntable on a transparent background keeps its alpha: the corner of a frame (WebP and PNG), of the
// animated WebP and of the zip's PNG frames is transparent, the model in the middle opaque.
TEST(TurntableApi, ATransparentTurntableKeepsItsAlpha) {
  json body = turntable_body(2, 32, 2);
  body["background"] = "transparent";
  const Reply r = post("/api/v1/turntables", body);
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string url = r.header("Location");
  ASSERT_EQ(test::finished_job(*server().client(), url)["status"], "done");
  const auto expect_cut_out = [](const uint8_t* rgba, int width, const std::string& what) {
    EXPECT_EQ(rgba[3], 0) << what;
    EXPECT_EQ(rgba[(size_t(width / 2) * size_t(width) + size_t(width / 2)) * 4 + 3], 255) << what;
  };
  int width = 0;
  const std::vector<uint8_t> animation = first_webp_frame(get(url + "/animation.webp").body, width);
  ASSERT_EQ(width, 32);
  expect_cut_out(animation.data(), width, "animation.webp");

  const Reply webp = get(url + "/frames/0?format=webp");
  int height = 0;
  uint8_t* frame =
      WebPDecodeRGBA(reinterpret_cast<const uint8_t*>(webp.body.data()), webp.body.size(), &width, &height);
  ASSERT_NE(frame, nullptr);
  expect_cut_out(frame, width, "frames/0?format=webp");
  WebPFree(frame);

  const auto members = unzip(get(url + "/frames.zip").body);
  ASSERT_TRUE(members.count("frame_0000.png"));
  const std::string& png = members.at("frame_0000.png");
  int channels = 0;
  stbi_uc* rgba = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()), &width,
                                        &height, &channels, 4);
  ASSERT_NE(rgba, nullptr);
  EXPECT_EQ(channels, 4);
  expect_cut_out(rgba, width, "frames.zip");
  stbi_image_free(rgba);
}

TEST(TurntableApi, CancelStopsItMidWay) {
  const Reply r = post("/api/v1/turntables", turntable_body(120, 64, 64));
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string url = r.header("Location");
  test::poll_until(
      "a running turntable with progress", [&] { return get(url).body_json(); },
      [](const json& st) { return st["status"] == "running" && st["progress"] > 0; });
  EXPECT_EQ(test::reply(server().client()->Delete(url.c_str())).status, 202);
  const json st = test::finished_job(*server().client(), url);
  EXPECT_EQ(st["status"], "cancelled");
  EXPECT_LT(st["frames_done"].get<int>(), 120);
  EXPECT_LT(st["progress"].get<double>(), 1.0);
  EXPECT_EQ(test::reply(server().client()->Delete(url.c_str())).status, 204);
  EXPECT_EQ(get(url).status, 404);
}

// The field a 400 names.
std::string refused_field(const json& body) {
  const Reply r = post("/api/v1/turntables", body);
  EXPECT_EQ(r.status, 400) << body.dump() << " -> " << r.body;
  if (r.status != 400) return "";
  const std::string message = r.body_json()["error"]["message"];
  EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field") << message;
  const auto open = message.find('\''), close = message.find('\'', open + 1);
  return message.substr(open + 1, close - open - 1);
}

TEST(TurntableApi, BadFieldsAreRefusedByName) {
  json body = turntable_body(4, 32, 4);
  body["scene"]["camera"] = {{"fov_deg", 30}};
  EXPECT_EQ(refused_field(body), "scene.camera");
  body = turntable_body(4, 32, 4);
  body.erase("turntable");
  EXPECT_EQ(refused_field(body), "turntable");
  body = turntable_body(0, 32, 4);
  EXPECT_EQ(refused_field(body), "turntable.frames");
  body = turntable_body(721, 8, 1);
  EXPECT_EQ(refused_field(body), "turntable.frames");
  body = turntable_body(720, 32, 1);  // 720 x 32 x 32 pixels, over --max-pixels
  EXPECT_EQ(refused_field(body), "turntable.frames");
  body = turntable_body(4, 32, 4);
  body["turntable"]["spin"] = 1;
  EXPECT_EQ(refused_field(body), "turntable.spin");
  body["turntable"] = {{"elevation_deg", 80}, {"elevation_sweep_deg", 20}};
  EXPECT_EQ(refused_field(body), "turntable.elevation_sweep_deg");
  body["turntable"] = {{"margin", 0}};
  EXPECT_EQ(refused_field(body), "turntable.margin");
  body["turntable"] = {{"azimuth_step_deg", 1000}};
  EXPECT_EQ(refused_field(body), "turntable.azimuth_step_deg");
  body["turntable"] = {{"object", 1}};
  EXPECT_EQ(refused_field(body), "turntable.object");
  body["turntable"] = 4;
  EXPECT_EQ(refused_field(body), "turntable");
  body = turntable_body(4, 32, 4);
  body["width"] = 0;
  EXPECT_EQ(refused_field(body), "width");

  const Reply format = get(turntable_url() + "/contact-sheet?format=exr");
  EXPECT_EQ(format.status, 400);
  EXPECT_NE(format.body.find("'format'"), std::string::npos) << format.body;
  const Reply fps = get(turntable_url() + "/animation.webp?fps=0");
  EXPECT_EQ(fps.status, 400);
  EXPECT_NE(fps.body.find("'fps'"), std::string::npos) << fps.body;
  const Reply curve = get(turntable_url() + "/contact-sheet?tone_mapping=filmic");
  EXPECT_EQ(curve.status, 400);
  EXPECT_NE(curve.body.find("'tone_mapping'"), std::string::npos) << curve.body;
  EXPECT_EQ(get(turntable_url() + "/frames/0?tone_mapping=agx").status, 200);
  const Reply size = get(turntable_url() + "/frames/0?size=0");
  EXPECT_EQ(size.status, 400);
  EXPECT_NE(size.body.find("'size'"), std::string::npos) << size.body;
  EXPECT_EQ(get("/api/v1/turntables/0123456789abcdef").status, 404);
}

TEST(TurntableApi, ListShowsTheTurntable) {
  const json list = get("/api/v1/turntables").body_json();
  bool found = false;
  for (const json& t : list["turntables"]) found = found || t["id"] == finished_turntable()["id"];
  EXPECT_TRUE(found) << list.dump();
}

// A finished 64x32 render of the quad.
std::string render_url() {
  static const std::string url = [] {
    json body = turntable_body(1, 32, 1);
    body.erase("turntable");
    body["width"] = 64;
    body["scene"]["camera"] = {{"fit", json::object()}};
    const Reply r = post("/api/v1/renders", body);
    EXPECT_EQ(r.status, 202) << r.body;
    const std::string location = r.header("Location");
    EXPECT_EQ(test::finished_job(*server().client(), location)["status"], "done");
    return location;
  }();
  return url;
}

TEST(ThumbnailApi, JpegAndWebpOfARenderAtSixteenPixels) {
  const Reply jpeg = get(render_url() + "/image?format=jpeg&size=16");
  ASSERT_EQ(jpeg.status, 200) << jpeg.body;
  EXPECT_EQ(jpeg.type(), "image/jpeg");
  const Decoded j = decode_stb(jpeg.body);
  EXPECT_EQ(j.width, 16);
  EXPECT_EQ(j.height, 8);

  const Reply webp = get(render_url() + "/image?format=webp&size=16");
  ASSERT_EQ(webp.status, 200) << webp.body;
  EXPECT_EQ(webp.type(), "image/webp");
  int width = 0, height = 0;
  ASSERT_TRUE(
      WebPGetInfo(reinterpret_cast<const uint8_t*>(webp.body.data()), webp.body.size(), &width, &height));
  EXPECT_EQ(width, 16);
  EXPECT_EQ(height, 8);

  const Decoded full = decode_stb(get(render_url() + "/image?format=jpeg&size=1000").body);
  EXPECT_EQ(full.width, 64);  // never enlarged
  EXPECT_EQ(full.height, 32);
}

TEST(ThumbnailApi, EtagRoundTripGives304) {
  const std::string path = render_url() + "/image?format=webp&size=16";
  const Reply first = get(path);
  ASSERT_EQ(first.status, 200);
  const std::string etag = first.header("ETag");
  ASSERT_FALSE(etag.empty());
  const Reply again = get(path, {{"If-None-Match", etag}});
  EXPECT_EQ(again.status, 304);
  EXPECT_TRUE(again.body.empty());
  EXPECT_EQ(get(render_url() + "/image?format=webp&size=15", {{"If-None-Match", etag}}).status, 200);
}

}  // namespace
}  // namespace lp
