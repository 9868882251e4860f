// POST /envmaps/{id}/samples (JSON or binary, streamed in chunks so memory stays bounded at any N)
// and GET /envmaps/{id}/samples.png.
#include <spdlog/spdlog.h>

#include <algorithm>

#include "api/sample_encoding.hpp"
#include "engine/envmap/sample_plot.hpp"
#include "server/reserved_content.hpp"
#include "server/routes.hpp"

namespace lp::server {
namespace {

constexpr uint64_t kChunk = 1 << 16;  // samples generated and sent at a time

struct SampleStream {
  std::shared_ptr<const EnvMapEntry> entry;  // keeps the map alive while streaming
  std::shared_ptr<const EnvMapSampler> sampler;
  api::SampleRequest request;
  bool binary = false;
  std::vector<EnvSample> buffer;
  uint64_t next = 0;
};

std::string json_prologue(const api::SampleRequest& r) {
  return fmt::format(R"({{"count":{},"seed":{},"strategy":"{}","luminance":"{}","samples":[)", r.spec.count,
                     r.spec.seed, enum_name(r.spec.strategy), enum_name(r.luminance));
}

// Produces the next chunk of the response body; false when there is nothing left.
bool next_chunk(SampleStream& s, std::string& out) {
  const uint64_t total = s.request.spec.count;
  if (s.next >= total) return false;
  const uint64_t n = std::min(kChunk, total - s.next);
  s.buffer.resize(n);
  generate_samples(*s.sampler, s.request.spec, s.next, s.buffer);
  out.reserve(out.size() + n * (s.binary ? sizeof(float) * api::kSampleRecordFloats : 192));
  for (uint64_t k = 0; k < n; ++k) {
    if (s.binary) {
      api::append_sample_binary(out, s.buffer[k]);
    } else {
      if (s.next + k > 0) out.push_back(',');
      api::append_sample_json(out, s.buffer[k]);
    }
  }
  s.next += n;
  if (!s.binary && s.next == total) out += "]}";
  return true;
}

void samples(App& app, const httplib::Request& req, httplib::Response& res) {
  auto stream = std::make_shared<SampleStream>();
  stream->entry = app.envmaps.get(path_param(req, 1));
  stream->request = api::parse_sample_request(api::parse_json_object(req.body), app.options.limits);
  stream->sampler = stream->entry->map->sampler(stream->request.luminance);
  stream->binary = req.get_header_value("Accept").find("application/octet-stream") != std::string::npos;
  if (stream->binary) {
    res.set_header("X-Sample-Count", std::to_string(stream->request.spec.count));
    res.set_header("X-Sample-Record-Layout", api::kSampleRecordLayout);
  }
  const char* type = stream->binary ? "application/octet-stream" : "application/json";
  if (stream->request.spec.count <= kChunk) {  // small: one body with its length, sent in one piece
    std::string body = stream->binary ? std::string() : json_prologue(stream->request);
    next_chunk(*stream, body);
    res.set_content(std::move(body), type);
    return;
  }
  res.set_chunked_content_provider(type, [stream](size_t, httplib::DataSink& sink) {
    std::string out = stream->next == 0 && !stream->binary ? json_prologue(stream->request) : std::string();
    try {
      if (!next_chunk(*stream, out)) {
        sink.done();
        return true;
      }
    } catch (const std::exception& e) {
      spdlog::error("sample stream failed: {}", e.what());
      return false;
    }
    return sink.write(out.data(), out.size());
  });
}

void samples_png(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const auto r = api::parse_sample_image_query(req.params, app.options.limits);
  const auto sampler = entry->map->sampler(r.samples.luminance);
  const int64_t w = entry->map->width(), h = entry->map->height();
  const int64_t drawing =
      int64_t(r.samples.spec.count) * int64_t(sizeof(EnvSample)) + sample_plot_bytes(w, h);
  send_png_picture(
      res, app.memory, w, h, drawing, fmt::format("a picture of {} samples", r.samples.spec.count), [&] {
        std::vector<EnvSample> drawn(r.samples.spec.count);
        generate_samples(*sampler, r.samples.spec, 0, drawn);
        return r.style == api::SampleImageStyle::Marks ? plot_sample_marks(*entry->map, drawn, r.tone)
                                                       : plot_sample_windows(*entry->map, drawn, r.tone);
      });
}

}  // namespace

void register_sample_routes(Router& router, App& app) {
  router.post("/api/v1/envmaps/{id}/samples", endpoint_of(app, samples));
  router.get("/api/v1/envmaps/{id}/samples.png", endpoint_of(app, samples_png));
}

}  // namespace lp::server
