// POST /envmaps/{id}/samples (JSON or binary, streamed in chunks so memory stays bounded at any N)
// and GET /envmaps/{id}/samples.png.
#include <spdlog/spdlog.h>

#include "api/sample_stream.hpp"
#include "engine/envmap/sample_plot.hpp"
#include "server/http/reserved_content.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

// The stream and the map it reads, kept alive together while the answer is sent.
struct MapSampleStream {
  std::shared_ptr<const EnvMapEntry> entry;
  api::SampleStream stream;
};

void samples(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const auto request = api::parse_sample_request(api::parse_json_object(req.body), app.options.limits);
  const bool binary = req.get_header_value("Accept").find("application/octet-stream") != std::string::npos;
  if (binary) {
    res.set_header("X-Sample-Count", std::to_string(request.spec.count));
    res.set_header("X-Sample-Record-Layout", api::kSampleRecordLayout);
  }
  auto s = std::make_shared<MapSampleStream>(MapSampleStream{
      entry, api::SampleStream(entry->map->sampler(request.luminance), request,
                               binary ? api::SampleEncoding::Binary : api::SampleEncoding::JsonDocument)});
  const char* type = binary ? "application/octet-stream" : "application/json";
  if (request.spec.count <=
      api::SampleStream::kChunk) {  // small: one body with its length, sent in one piece
    std::string body;
    s->stream.next(body);
    res.set_content(std::move(body), type);
    return;
  }
  res.set_chunked_content_provider(type, [s](size_t, httplib::DataSink& sink) {
    std::string out;
    try {
      if (!s->stream.next(out)) {
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
  router.get("/api/v1/envmaps/{id}/samples.png", endpoint_of(app, samples_png), Caching::Revalidate);
}

}  // namespace lp::server
