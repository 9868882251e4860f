#include "server/renders/render_record.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace lp::server {
namespace {

constexpr int kRecordVersion = 1;

using Clock = std::chrono::system_clock;

int64_t to_ms(Clock::time_point t) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count();
}

nlohmann::json ranges_json(const std::vector<render::SampleRange>& ranges) {
  auto out = nlohmann::json::array();
  for (const auto& r : ranges) out.push_back({r.first, r.end});
  return out;
}

// Disjoint ranges [first, end) that hold `spp_done` samples per pixel together.
std::vector<render::SampleRange> parse_ranges(const nlohmann::json& j, int spp_done) {
  std::vector<render::SampleRange> out;
  for (const auto& r : j) out.push_back({r.at(0).get<uint32_t>(), r.at(1).get<uint32_t>()});
  std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.first < b.first; });
  int64_t total = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i].end <= out[i].first || (i > 0 && out[i].first < out[i - 1].end))
      throw std::invalid_argument("the sample ranges done overlap or are empty");
    total += out[i].count();
  }
  if (!out.empty() && total != spp_done)
    throw std::invalid_argument("the sample ranges done do not hold the samples done");
  return out;
}

// {"OBJECT INDEX": HASH, ...}
nlohmann::json model_hashes_json(const ModelHashes& hashes) {
  auto out = nlohmann::json::object();
  for (const auto& [object, hash] : hashes) out[std::to_string(object)] = hash;
  return out;
}

ModelHashes parse_model_hashes(const nlohmann::json& j) {
  ModelHashes out;
  for (const auto& [key, hash] : j.items()) {
    size_t object = 0;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), object);
    if (ec != std::errc() || end != key.data() + key.size())
      throw std::invalid_argument("a model hash is not keyed by an object index");
    out[object] = hash.get<std::string>();
  }
  return out;
}

}  // namespace

nlohmann::json record_json(const RenderRecord& r) {
  return {{"version", kRecordVersion},
          {"id", r.id},
          {"created_ms", to_ms(r.created)},
          {"request", r.request},
          {"status", enum_name(r.status)},
          {"error", r.error ? nlohmann::json{{"code", r.error->code}, {"message", r.error->message}}
                            : nlohmann::json()},
          {"spp_done", r.spp_done},
          {"sample_ranges_done", ranges_json(r.ranges_done)},
          {"image_file", r.image_file},
          {"denoise_s", r.denoise_s ? nlohmann::json(*r.denoise_s) : nlohmann::json()},
          {"envmap_fingerprint", r.envmap_fingerprint},
          {"model_hashes", model_hashes_json(r.model_hashes)},
          {"elapsed_s", r.elapsed_s},
          {"samples", r.stats.samples},
          {"rays", r.stats.rays},
          {"render_s", r.render_s}};
}

RenderRecord parse_render_record(const nlohmann::json& j) {
  if (j.at("version").get<int>() != kRecordVersion) throw std::invalid_argument("unknown record version");
  RenderRecord r;
  r.id = j.at("id").get<std::string>();
  r.created = Clock::time_point(std::chrono::milliseconds(j.at("created_ms").get<int64_t>()));
  r.request = j.at("request");
  if (!r.request.is_object()) throw std::invalid_argument("the request is not an object");
  const auto status = parse_enum<JobStatus>(j.at("status").get<std::string>());
  if (!status) throw std::invalid_argument("unknown status");
  r.status = *status;
  if (const auto& e = j.at("error"); !e.is_null())
    r.error = JobError{e.at("code").get<std::string>(), e.at("message").get<std::string>()};
  r.spp_done = j.at("spp_done").get<int>();
  r.image_file = j.at("image_file").get<std::string>();
  if (const auto d = j.find("denoise_s"); d != j.end() && !d->is_null()) r.denoise_s = d->get<double>();
  r.ranges_done = parse_ranges(j.value("sample_ranges_done", nlohmann::json::array()), r.spp_done);
  r.envmap_fingerprint = j.at("envmap_fingerprint").get<std::string>();
  r.model_hashes = parse_model_hashes(j.value("model_hashes", nlohmann::json::object()));
  r.elapsed_s = j.at("elapsed_s").get<double>();
  r.stats = {j.at("samples").get<uint64_t>(), j.at("rays").get<uint64_t>()};
  r.render_s = j.at("render_s").get<double>();
  if (r.spp_done < 0 || (r.spp_done > 0) == r.image_file.empty())
    throw std::invalid_argument("the samples done and the image file disagree");
  if (r.denoise_s && r.image_file.empty())
    throw std::invalid_argument("a denoised image is named without its image");
  if (r.image_file.find('/') != std::string::npos)
    throw std::invalid_argument("the image file is not a plain name");
  return r;
}

}  // namespace lp::server
