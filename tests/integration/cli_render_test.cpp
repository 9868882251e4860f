// `lightprobe render SCENE.json | MODEL`, the real tool: a white furnace renders its analytic value, a
// scene with a model next to the scene file, and a model file alone, render the image the server renders
// for the same request, progress goes to standard error, and bad scenes fail with the API's messages.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/exr_channels.hpp"
#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"
#include "support/white_map.hpp"
#include "support/white_sphere.hpp"

namespace lp {
namespace {

using nlohmann::json;

void write_text(const std::filesystem::path& path, const std::string& text) {
  write_file(path, std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

// A 64 x 32 map of radiance 1 everywhere, as white.pfm in `folder`.
void write_white_map(const std::filesystem::path& folder) {
  Image white(64, 32);
  for (int y = 0; y < white.height(); ++y)
    for (int x = 0; x < white.width(); ++x) white.set(x, y, {1, 1, 1});
  write_file(folder / "white.pfm", write_pfm(white));
}

// A diffuse sphere of albedo 0.5 in a furnace of radiance 1 has radiance 0.5 everywhere: the centre 4 x 4
// pixels of a 32 x 32 render at 32 samples each lie within 0.02 of it; around it the camera sees the
// map, 1.
void expect_furnace_image(const std::filesystem::path& file) {
  const Image image = read_image_file(file).image;
  ASSERT_EQ(image.width(), 32);
  ASSERT_EQ(image.height(), 32);
  double centre = 0;
  for (int y = 14; y < 18; ++y)
    for (int x = 14; x < 18; ++x) centre += image.at(x, y).x / 16.0;
  EXPECT_NEAR(centre, 0.5, 0.02);
  EXPECT_NEAR(image.at(0, 0).y, 1.0, 1e-6);
}

TEST(CliRender, AWhiteFurnaceRendersItsAnalyticValue) {
  const test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "maps");
  write_white_map(dir.path() / "maps");
  std::filesystem::create_directories(dir.path() / "scenes");
  write_text(
      dir.path() / "scenes" / "furnace.json",
      R"({"envmap":"../maps/white.pfm","scene":{"preset":"furnace"},"width":32,"height":32,"spp":32})");
  const test::CliRun run = test::run_cli({"render", "scenes/furnace.json", "-o", "furnace.exr"}, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_TRUE(run.out.empty());
  expect_furnace_image(dir.path() / "furnace.exr");
}

// --sampling adaptive: spp is the mean, and the furnace keeps its value; the bar is drawn and ended.
TEST(CliRender, AnAdaptiveFurnaceRendersItsAnalyticValue) {
  const test::TempDir dir;
  write_white_map(dir.path());
  write_text(dir.path() / "furnace.json",
             R"({"envmap":"white.pfm","scene":{"preset":"furnace"},"width":32,"height":32,"spp":32})");
  const test::CliRun run =
      test::run_cli({"render", "furnace.json", "--sampling", "adaptive", "-o", "furnace.exr"}, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_NE(run.err.find("\nrender 100%  "), std::string::npos) << run.err;
  expect_furnace_image(dir.path() / "furnace.exr");
}

TEST(CliRender, ShowsProgressUnlessQuiet) {
  const test::TempDir dir;
  write_text(dir.path() / "scene.json", R"({"envmap":"default","width":32,"height":16,"spp":1})");
  const test::CliRun shown = test::run_cli({"render", "scene.json", "-o", "a.exr"}, dir.path());
  ASSERT_EQ(shown.exit_status, 0) << shown.err;
  EXPECT_EQ(shown.err.rfind("render 10%  ", 0), 0u) << shown.err;
  const test::CliRun quiet = test::run_cli({"render", "scene.json", "-o", "b.exr", "--quiet"}, dir.path());
  ASSERT_EQ(quiet.exit_status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

// The image the shared server renders for `body`, as EXR.
Image served_render(const std::string& body) {
  const auto client = test::shared_server().client();
  const json accepted = test::reply(client->Post("/api/v1/renders", body, "application/json")).body_json();
  const std::string id = accepted["id"];
  EXPECT_EQ(test::finished_render(*client, id)["status"], "done");
  const test::Reply exr = test::reply(client->Get(("/api/v1/renders/" + id + "/image?format=exr").c_str()));
  return read_image(std::span(reinterpret_cast<const uint8_t*>(exr.body.data()), exr.body.size())).image;
}

// The same samples give the same image up to float summation order.
void expect_same_image(const std::string& exr, const Image& served) {
  const Image rendered =
      read_image(std::span(reinterpret_cast<const uint8_t*>(exr.data()), exr.size())).image;
  ASSERT_EQ(rendered.width(), served.width());
  ASSERT_EQ(rendered.height(), served.height());
  for (int y = 0; y < served.height(); ++y)
    for (int x = 0; x < served.width(); ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rendered.at(x, y)[c], served.at(x, y)[c], 1e-5f * (1 + served.at(x, y)[c]))
            << x << "," << y << " channel " << c;
}

// The same body rendered by the server (the model inside its --data-dir, tests/data) and by the tool (the
// model beside the scene file).
TEST(CliRender, AModelBesideTheSceneFileRendersAsTheServerRendersIt) {
  const std::string body =
      R"({"envmap":"forest_exr","scene":{"objects":[{"type":"mesh","path":"models/quad.glb"}]},)"
      R"("width":24,"height":24,"spp":4,"seed":5})";
  const Image served = served_render(body);
  ASSERT_EQ(served.width(), 24);

  const test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "models");
  std::filesystem::copy_file(test::model_path("quad.glb"), dir.path() / "models" / "quad.glb");
  json scene = json::parse(body);
  scene["envmap"] = test::envmap_path("forest.exr").string();
  write_text(dir.path() / "scene.json", scene.dump());
  const test::CliRun run =
      test::run_cli({"render", (dir.path() / "scene.json").string(), "--format", "exr", "-q"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  expect_same_image(run.out, served);
}

// A model file alone is the body whose scene is that one mesh and no camera: framed by the default fit,
// with the model's own materials, under the map --envmap names. The server renders that body alike.
TEST(CliRender, AModelFileRendersAsARequestNamingOnlyThatMesh) {
  for (const std::string model : {"quad.glb", "obj/quad.obj"}) {
    SCOPED_TRACE(model);
    const Image served = served_render(R"({"envmap":"forest_exr","scene":{"objects":[{"type":"mesh","path":)"
                                       R"("models/)" +
                                       model + R"("}]},"width":24,"height":20,"spp":4})");
    ASSERT_EQ(served.height(), 20);
    const test::CliRun run = test::run_cli(
        {"render", test::model_path(model).string(), "--envmap", test::envmap_path("forest.exr").string(),
         "--width", "24", "--height", "20", "--spp", "4", "--format", "exr", "--no-denoise", "-q"});
    ASSERT_EQ(run.exit_status, 0) << run.err;
    expect_same_image(run.out, served);
  }
}

// A model file's picture is a thumbnail: denoised unless --no-denoise, as --denoise asks.
TEST(CliRender, AModelFileIsDenoisedByDefault) {
  const auto render = [](const std::string& flag) {
    std::vector<std::string> args = {"render",   test::model_path("quad.glb").string(),
                                     "--envmap", test::envmap_path("forest.exr").string(),
                                     "--width",  "24",
                                     "--height", "20",
                                     "--spp",    "2",
                                     "--format", "exr",
                                     "-q"};
    if (!flag.empty()) args.push_back(flag);
    const test::CliRun run = test::run_cli(args);
    EXPECT_EQ(run.exit_status, 0) << run.err;
    return run.out;
  };
  const std::string by_default = render(""), denoised = render("--denoise"), raw = render("--no-denoise");
  EXPECT_EQ(by_default, denoised);
  EXPECT_NE(by_default, raw);
}

// `lightprobe render model.glb -o thumb.png`, as f3d --output: a PNG of the size asked for. Under a map
// of radiance 1 everywhere, every pixel that sees the map is the corner's colour; the middle pixels see the
// model (its grey-green checker texture, darker than the map).
TEST(CliRender, AModelFileBecomesAThumbnail) {
  const test::TempDir dir;
  write_white_map(dir.path());
  const test::CliRun run =
      test::run_cli({"render", test::model_path("quad.glb").string(), "--envmap", "white.pfm", "--width",
                     "40", "--height", "30", "--spp", "4", "-o", "thumb.png", "-q"},
                    dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "thumb.png"));
  ASSERT_EQ(png.width, 40);
  ASSERT_EQ(png.height, 30);
  const auto luma = [&](int x, int y) {
    const size_t i = (size_t(y) * 40 + size_t(x)) * 3;
    return int(png.rgb[i]) + png.rgb[i + 1] + png.rgb[i + 2];
  };
  // Denoised: the map's corners agree to the network's error at the image's corners (8 of 765 measured).
  EXPECT_NEAR(luma(39, 29), luma(0, 0), 20);
  for (const auto& [x, y] : {std::pair{20, 15}, std::pair{18, 13}, std::pair{22, 17}})
    EXPECT_LT(luma(x, y), luma(0, 0) - 30) << x << "," << y << ": the map, not the model";
}

// The PNG of a render of no objects on the white map (radiance 1 everywhere), one stop down and with
// gamma 1, written with the extra options `more`: the one value of every pixel, or -1 if they differ.
int white_render_png(const std::vector<std::string>& more) {
  const test::TempDir dir;
  write_white_map(dir.path());
  write_text(dir.path() / "scene.json",
             R"({"envmap":"white.pfm","scene":{"objects":[]},"width":4,"height":2,"spp":1})");
  std::vector<std::string> args = {"render", "scene.json", "-o", "white.png", "--exposure",
                                   "-1",     "--gamma",    "1",  "-q"};
  args.insert(args.end(), more.begin(), more.end());
  const test::CliRun run = test::run_cli(args, dir.path());
  EXPECT_EQ(run.exit_status, 0) << run.err;
  const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "white.png"));
  if (png.rgb.empty()) return -1;
  for (const uint8_t v : png.rgb)
    if (v != png.rgb[0]) return -1;
  return png.rgb[0];
}

// A render's picture is PBR Neutral unless told: 0.5 - 0.04 = 0.46, 117.3 at gamma 1, written 117; the
// option (or the scene's "tone_mapping") chooses another curve: reinhard 0.5 / 1.5 = 0.3333, 85.
TEST(CliRender, ThePictureIsNeutralUnlessToneMappingSaysOtherwise) {
  EXPECT_EQ(white_render_png({}), 117);
  EXPECT_EQ(white_render_png({"--tone-mapping", "neutral"}), 117);
  EXPECT_EQ(white_render_png({"--tone-mapping", "reinhard"}), 85);
  EXPECT_EQ(white_render_png({"--tone-mapping", "standard"}), 128);
}

// A scene of no objects shows the map everywhere: a white map, radiance 1, darkened one stop and written
// with gamma 1 and no curve is 0.5 * 255 = 127.5, written as 128, in every pixel. A map named on the
// command line is found from the working directory.
TEST(CliRender, FieldsOnTheCommandLineReplaceTheFilesAndPngIsToneMapped) {
  const test::TempDir dir;
  write_white_map(dir.path());
  std::filesystem::create_directories(dir.path() / "scenes");
  write_text(dir.path() / "scenes" / "scene.json",
             R"({"envmap":"default","scene":{"objects":[]},"width":64,"height":64,"spp":1})");
  const test::CliRun run = test::run_cli(
      {"render", "scenes/scene.json", "--envmap", "white.pfm", "--width", "4", "--height", "2", "-o",
       "white.png", "--exposure", "-1", "--gamma", "1", "--tone-mapping", "standard", "-q"},
      dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "white.png"));
  ASSERT_EQ(png.width, 4);
  ASSERT_EQ(png.height, 2);
  for (const uint8_t v : png.rgb) EXPECT_EQ(v, 128);
}

// --background transparent: an RGBA PNG whose corner (the map) has alpha 0 and whose middle (the model)
// alpha 255; with --ground (a shadow catcher under the model) and --clamp, the request's other fields.
TEST(CliRender, ATransparentBackgroundGivesAPngWithAlpha) {
  const test::TempDir dir;
  const test::CliRun run = test::run_cli(
      {"render", test::model_path("quad.glb").string(), "--background", "transparent", "--ground", "--clamp",
       "4", "--width", "40", "--height", "30", "--spp", "4", "-o", "cut.png", "-q"},
      dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const std::vector<uint8_t> bytes = test::read_bytes(dir.path() / "cut.png");
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  const std::vector<uint8_t> rgba(pixels, pixels + size_t(width) * size_t(height) * 4);
  stbi_image_free(pixels);
  EXPECT_EQ(channels, 4);
  ASSERT_EQ(width, 40);
  EXPECT_EQ(rgba[3], 0);                                 // (0, 0)
  EXPECT_EQ(rgba[(size_t(15) * 40 + 20) * 4 + 3], 255);  // (20, 15)
}

std::string text_of(const std::vector<uint8_t>& bytes) {
  return {bytes.begin(), bytes.end()};
}

// The white sphere (support/white_sphere.hpp) at 33 x 33 pixels, on a white map `envmap` names.
json white_sphere_scene(const std::string& envmap) {
  json body = test::white_sphere_body(envmap, 33, 4);
  body["seed"] = 3;
  return body;
}

// --passes with an EXR output: one EXR with every pass as a channel, named as the server's pass=all names
// them, and equal to the server's for the same request; the albedo of the white sphere is 1 wherever the
// sphere covers the whole pixel.
TEST(CliRender, PassesAreTheChannelsOfOneExrAsTheServerWritesThem) {
  const test::TempDir dir;
  write_white_map(dir.path());
  write_text(dir.path() / "sphere.json", white_sphere_scene("white.pfm").dump());
  const test::CliRun run = test::run_cli(
      {"render", "sphere.json", "--passes", "albedo,normal,depth,alpha", "-o", "passes.exr", "-q"},
      dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::ExrChannels exr = test::exr_channels(text_of(test::read_bytes(dir.path() / "passes.exr")));
  std::set<std::string> names;
  for (const auto& [name, _] : exr.channels) names.insert(name);
  EXPECT_EQ(names, (std::set<std::string>{"Albedo.B", "Albedo.G", "Albedo.R", "Alpha.A", "B", "Depth.Z", "G",
                                          "Ns.X", "Ns.Y", "Ns.Z", "R"}));
  ASSERT_EQ(exr.width, 33);

  const auto& alpha = exr.channels.at("Alpha.A");
  int covered = 0;
  for (size_t i = 0; i < alpha.size(); ++i) {
    if (alpha[i] < 1) continue;
    ++covered;
    for (const char* c : {"Albedo.R", "Albedo.G", "Albedo.B"})
      EXPECT_NEAR(exr.channels.at(c)[i], 1.0f, 1e-3f) << c << " at " << i;
  }
  EXPECT_GT(covered, 200);                          // the sphere spans about 17 x 17 pixels
  EXPECT_EQ(exr.channels.at("Albedo.R")[0], 0.0f);  // the map has none

  json body = white_sphere_scene(test::ensure_white_map(*test::white_map_server().client(), "white"));
  body["passes"] = {"albedo", "normal", "depth", "alpha"};
  const auto client = test::white_map_server().client();
  const json accepted =
      test::reply(client->Post("/api/v1/renders", body.dump(), "application/json")).body_json();
  const std::string id = accepted["id"];
  EXPECT_EQ(test::finished_render(*client, id)["status"], "done");
  const test::Reply all =
      test::reply(client->Get(("/api/v1/renders/" + id + "/image?pass=all&format=exr").c_str()));
  const test::ExrChannels served = test::exr_channels(all.body);
  ASSERT_EQ(served.channels.size(), exr.channels.size());
  for (const auto& [name, values] : served.channels) {
    const auto& rendered = exr.channels.at(name);
    ASSERT_EQ(rendered.size(), values.size()) << name;
    for (size_t i = 0; i < values.size(); ++i)
      if (std::isinf(values[i]))
        EXPECT_EQ(rendered[i], values[i]) << name << " at " << i;
      else
        EXPECT_NEAR(rendered[i], values[i], 1e-5f * (1 + std::abs(values[i]))) << name << " at " << i;
  }
}

// --passes with a PNG output: the colour in OUT and each pass beside it as OUT.NAME.png, as the server's
// PNG of that pass (depth: white at the nearest point, black where no ray hit).
TEST(CliRender, PassesBesideAPngAreFilesOfTheirOwn) {
  const test::TempDir dir;
  write_white_map(dir.path());
  write_text(dir.path() / "sphere.json", white_sphere_scene("white.pfm").dump());
  const test::CliRun run = test::run_cli(
      {"render", "sphere.json", "--passes", "albedo,depth", "-o", "thumb.png", "-q"}, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  for (const char* file : {"thumb.png", "thumb.albedo.png"})
    EXPECT_EQ(test::decode_png(test::read_bytes(dir.path() / file)).width, 33) << file;
  const test::PngPixels depth = test::decode_png(test::read_bytes(dir.path() / "thumb.depth.png"));
  ASSERT_EQ(depth.width, 33);
  EXPECT_EQ(depth.rgb[0], 0);
  EXPECT_EQ(depth.rgb[(size_t(16) * 33 + 16) * 3], 255);
}

// A pass that would be a file of its own has nowhere to go on standard output or beside a turntable's
// frames: refused before rendering.
TEST(CliRender, PassesWithNowhereToGoAreRefused) {
  const test::TempDir dir;
  const std::string message =
      "bad_request: the 'depth' pass is written as a file of its own beside -o FILE unless the output is "
      "EXR: ";
  test::expect_cli_refusals(
      {"render", test::model_path("quad.glb").string(), "--passes", "depth"},
      {{{"--format", "png"},
        message + "give -o FILE; ask for format exr, or leave the pass out of \"passes\""},
       {{"--turntable", "2", "-o", "."},
        message + "a turntable writes no passes beside its frames; ask for format exr, or leave the pass out "
                  "of \"passes\""}},
      dir.path());
}

TEST(CliRender, BadScenesFailAsTheApiAnswersThem) {
  const test::TempDir dir;
  const auto client = test::shared_server().client();
  for (const std::string body : {
           R"({"envmap":"default","spp":0})",
           R"({"envmap":"default","width":100000})",
           R"({"envmap":"default","scene":{"preset":"teapot"}})",
           R"({"envmap":"default","scene":{"objects":[{"type":"sphere","radius":1}]}})",
           R"({"envmap":"default","lighting":{"mode":"sun"}})",
           R"({"envmap":"default","colour":"red"})",
           R"({"envmap":"default","sampling":"auto"})",
           R"({"scene":{}})",
           R"([1,2])",
       }) {
    SCOPED_TRACE(body);
    write_text(dir.path() / "bad.json", body);
    const test::CliRun run = test::run_cli({"render", "bad.json", "-q"}, dir.path());
    const test::Reply api = test::reply(client->Post("/api/v1/renders", body, "application/json"));
    EXPECT_EQ(api.status, 400);
    EXPECT_EQ(run.exit_status, 2);
    EXPECT_EQ(run.err, test::cli_error_line(api.body_json()));
    EXPECT_TRUE(run.out.empty());
  }
}

TEST(CliRender, MissingFilesNameTheirField) {
  const test::TempDir dir;
  const auto error_of = [&](const std::string& body) {
    write_text(dir.path() / "scene.json", body);
    const test::CliRun run = test::run_cli({"render", "scene.json", "-q"}, dir.path());
    EXPECT_EQ(run.exit_status, 2) << body;
    return run.err;
  };
  EXPECT_EQ(error_of(R"({"envmap":"nowhere.exr"})"),
            "error: invalid_field: field 'envmap': cannot open nowhere.exr\n");
  EXPECT_EQ(error_of(R"({"envmap":"default","scene":{"objects":[{"type":"mesh","path":"none.obj"}]}})")
                .rfind("error: invalid_field: field 'scene.objects[0].path': ", 0),
            0u);
  EXPECT_EQ(error_of("{\"envmap\":"), "error: invalid_json: the scene file scene.json is not valid JSON\n");
  const test::CliRun missing = test::run_cli({"render", "no-scene.json"}, dir.path());
  EXPECT_EQ(missing.exit_status, 2);
  EXPECT_EQ(missing.err, "error: not_found: cannot open the scene file no-scene.json\n");
}

}  // namespace
}  // namespace lp
