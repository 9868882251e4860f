// Models against --max-memory-mb on the real server: a model's memory is reserved from the counts and
// image headers its files state before its geometry and textures are allocated, so a model that does
// not fit is refused with 507 without the process ever holding it; requests for the same model at once
// share one load. Each test reads the server's peak resident memory (VmHWM) and holds it to the
// process as it started plus the budget plus kMargin.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

constexpr int64_t kMiB = int64_t{1} << 20;
constexpr int kBudgetMb = 256;
// What the process may hold beyond its start and the budget: request and response buffers, the
// parsed glTF document, allocator slack.
constexpr int64_t kMargin = 48 * kMiB;

// The process's peak resident memory so far.
int64_t peak_rss(int pid) {
  std::ifstream status(fmt::format("/proc/{}/status", pid));
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
  ADD_FAILURE() << "no VmHWM in /proc/" << pid << "/status";
  return 0;
}

void append_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xFF);
}

void append_u32_be(std::string& out, uint32_t v) {
  for (int i = 3; i >= 0; --i) out += char((v >> (8 * i)) & 0xFF);
}

void png_chunk(std::string& out, const char* type, const std::string& data) {
  append_u32_be(out, uint32_t(data.size()));
  const std::string body = type + data;
  out += body;
  append_u32_be(out, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

// A 16-bit grey PNG of size x size pixels, every one `value`: tens of kilobytes for tens of megabytes
// of pixels.
std::string grey16_png(int size, uint16_t value) {
  std::string row(1 + size_t(size) * 2, '\0');  // filter byte 0, big-endian samples
  for (int x = 0; x < size; ++x) {
    row[1 + size_t(x) * 2] = char(value >> 8);
    row[2 + size_t(x) * 2] = char(value & 0xFF);
  }
  z_stream z{};
  deflateInit(&z, Z_BEST_COMPRESSION);
  std::string idat;
  std::vector<unsigned char> buffer(1 << 16);
  for (int y = 0; y < size; ++y) {
    z.next_in = reinterpret_cast<Bytef*>(row.data());
    z.avail_in = uInt(row.size());
    const int flush = y + 1 == size ? Z_FINISH : Z_NO_FLUSH;
    do {
      z.next_out = buffer.data();
      z.avail_out = uInt(buffer.size());
      deflate(&z, flush);
      idat.append(reinterpret_cast<char*>(buffer.data()), buffer.size() - z.avail_out);
    } while (z.avail_out == 0 || (flush == Z_FINISH && z.avail_in > 0));
  }
  deflateEnd(&z);
  std::string header;
  append_u32_be(header, uint32_t(size));
  append_u32_be(header, uint32_t(size));
  header += std::string("\x10\x00\x00\x00\x00", 5);  // depth 16, grey, deflate, no filter, no interlace
  std::string out = "\x89PNG\r\n\x1a\n";
  png_chunk(out, "IHDR", header);
  png_chunk(out, "IDAT", idat);
  png_chunk(out, "IEND", "");
  return out;
}

// A .glb of one textured triangle whose base colour and emission are the two images.
std::string textured_triangle_glb(const std::string& base_color, const std::string& emission) {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  const float uvs[6] = {0, 0, 1, 0, 0, 1};
  std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
  bin.append(reinterpret_cast<const char*>(uvs), sizeof uvs);
  const size_t first_image = bin.size();
  bin += base_color;
  const size_t second_image = bin.size();
  bin += emission;
  const json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
      {"materials",
       {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
         {"emissiveTexture", {{"index", 1}}},
         {"emissiveFactor", {1, 1, 1}}}}},
      {"textures", {{{"source", 0}}, {{"source", 1}}}},
      {"images",
       {{{"bufferView", 2}, {"mimeType", "image/png"}}, {{"bufferView", 3}, {"mimeType", "image/png"}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 3},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 0, 1}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}},
        {{"buffer", 0}, {"byteOffset", first_image}, {"byteLength", base_color.size()}},
        {{"buffer", 0}, {"byteOffset", second_image}, {"byteLength", emission.size()}}}},
      {"buffers", {{{"byteLength", bin.size()}}}}};
  std::string text = doc.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  std::string out = "glTF";
  append_u32(out, 2);
  append_u32(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  append_u32(out, uint32_t(text.size()));
  out += "JSON" + text;
  append_u32(out, uint32_t(bin.size()));
  out += "BIN" + std::string(1, '\0') + bin;
  return out;
}

// Two 16-bit 4096 x 4096 textures: 268 MiB of float texels with their mip levels, each.
std::string oversized_glb(uint16_t value) {
  const std::string image = grey16_png(4096, value);
  return textured_triangle_glb(image, image);
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A server with a data folder of models, --max-memory-mb kBudgetMb, and its resident memory at start.
class ModelServer {
 public:
  explicit ModelServer(const std::vector<std::pair<std::string, std::string>>& files) {
    for (const auto& [name, bytes] : files) write_file(data_.path() / name, bytes);
    server_ = std::make_unique<test::ServerProcess>(std::vector<std::string>{
        "--max-memory-mb", std::to_string(kBudgetMb), "--data-dir", data_.path().string()});
    start_ = peak_rss(server_->pid());
  }
  Reply render(const std::string& model) const {
    const json mesh = {{"type", "mesh"}, {"path", model}};
    const json body = {
        {"envmap", "default"}, {"width", 16}, {"height", 16}, {"spp", 1}, {"scene", {{"objects", {mesh}}}}};
    return test::reply(server_->client()->Post("/api/v1/renders", body.dump(), "application/json"));
  }
  Reply upload(const std::string& name, const std::string& bytes) const {
    return test::reply(
        server_->client()->Post(("/api/v1/assets?name=" + name).c_str(), bytes, "application/octet-stream"));
  }
  // Renders of each model at once, one request each.
  std::vector<Reply> render_at_once(const std::vector<std::string>& models) const {
    std::vector<std::future<Reply>> replies;
    for (const std::string& m : models)
      replies.push_back(std::async(std::launch::async, [&] { return render(m); }));
    std::vector<Reply> out;
    for (auto& r : replies) out.push_back(r.get());
    return out;
  }
  json finished(const Reply& accepted) const {
    return test::finished_render(*server_->client(), accepted.body_json()["id"]);
  }
  // Peak resident memory above the process at start, checked against the budget and kMargin.
  void expect_peak_within_budget() const {
    const int64_t peak = peak_rss(server_->pid());
    EXPECT_LE(peak - start_, kBudgetMb * kMiB + kMargin)
        << fmt::format("VmHWM {} MiB, {} MiB at start", peak / kMiB, start_ / kMiB);
    std::printf("[ VmHWM    ] %lld MiB (%lld MiB at start)\n", static_cast<long long>(peak / kMiB),
                static_cast<long long>(start_ / kMiB));
  }

 private:
  test::TempDir data_;
  std::unique_ptr<test::ServerProcess> server_;
  int64_t start_ = 0;
};

void expect_507(const Reply& r) {
  EXPECT_EQ(r.status, 507) << r.body;
  if (r.status == 507) {
    EXPECT_EQ(r.body_json()["error"]["code"], "insufficient_memory");
  }
}

TEST(ModelMemory, TwoSixteenBitTexturesOverTheBudgetAreRefusedBeforeTheyAreDecoded) {
  const std::string glb = oversized_glb(0x8000);
  EXPECT_LT(glb.size(), size_t{512} << 10);
  const ModelServer s({{"heavy.glb", glb}});
  expect_507(s.upload("heavy", glb));
  expect_507(s.render("heavy.glb"));
  s.expect_peak_within_budget();
}

TEST(ModelMemory, FourRequestsForOneOversizedModelAtOnceAreRefusedWithoutLoadingIt) {
  const ModelServer s({{"heavy.glb", oversized_glb(0x8000)}});
  for (const Reply& r : s.render_at_once({"heavy.glb", "heavy.glb", "heavy.glb", "heavy.glb"})) expect_507(r);
  s.expect_peak_within_budget();
}

TEST(ModelMemory, FourOversizedModelsAtOnceAreRefusedWithoutLoadingThem) {
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> names;
  for (int i = 0; i < 4; ++i) {
    names.push_back(fmt::format("heavy{}.glb", i));
    files.emplace_back(names.back(), oversized_glb(uint16_t(0x4000 * i + 100)));
  }
  const ModelServer s(files);
  for (const Reply& r : s.render_at_once(names)) expect_507(r);
  s.expect_peak_within_budget();
}

TEST(ModelMemory, ATwoMillionTriangleObjIsRefusedFromItsCounts) {
  const ModelServer s({{"grid.obj", test::grid_obj(1000)}});  // 2,000,000 triangles, 68 MB of text
  expect_507(s.render("grid.obj"));
  s.expect_peak_within_budget();
}

// Two 16-bit 2048 x 2048 textures (67 MiB each with their mip levels) fit the budget once, not four
// times: four requests at once share one load, and all four render.
TEST(ModelMemory, FourRequestsForAModelThatFitsShareOneLoad) {
  const std::string image = grey16_png(2048, 0x8000);
  const ModelServer s({{"fits.glb", textured_triangle_glb(image, image)}});
  for (const Reply& r : s.render_at_once({"fits.glb", "fits.glb", "fits.glb", "fits.glb"})) {
    ASSERT_EQ(r.status, 202) << r.body;
    EXPECT_EQ(s.finished(r)["status"], "done");
  }
  s.expect_peak_within_budget();
}

}  // namespace
}  // namespace lp
