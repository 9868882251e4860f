#include "api/thumbnail_params.hpp"

#include "api/preview_params.hpp"

namespace lp::api {

std::optional<int> parse_image_size(const Query& q) {
  const auto text = query_string(q, kImageSize.name);
  if (!text || text->empty()) return std::nullopt;
  return int(query_int(q, kImageSize.name, 0, int64_t(kImageSize.range.min), int64_t(kImageSize.range.max)));
}

int parse_animation_fps(const Query& q) {
  const NumberField& f = kAnimationFps;
  return int(query_int(q, f.name, int64_t(*f.fallback), int64_t(f.range.min), int64_t(f.range.max)));
}

ToneMap parse_turntable_tone(const Query& q) {
  ToneMap tone = parse_tone_map(q);
  tone.curve = query_enum(q, "tone_mapping", kTurntableToneCurve);
  return tone;
}

std::vector<std::string> eight_bit_format_names() {
  std::vector<std::string> names;
  for (const auto& e : enum_entries(ImageFormat{}))
    if (is_eight_bit(e.value)) names.emplace_back(e.name);
  return names;
}

ImageFormat parse_eight_bit_format(const Query& q) {
  return *parse_enum<ImageFormat>(
      query_enum(q, "format", enum_name(ImageFormat::Png), eight_bit_format_names()));
}

}  // namespace lp::api
