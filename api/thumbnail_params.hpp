#pragma once
// The query parameters of 8-bit pictures made smaller or put together: `size` (the longest side in
// pixels, never enlarging), `fps` of an animation, and a `format` that must be an 8-bit one.
#include <optional>
#include <string>
#include <vector>

#include "api/parameters.hpp"
#include "api/params.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

inline constexpr NumberField kImageSize{"size", std::nullopt, {1, double(limits::kMaxImageDimension)}};
inline constexpr NumberField kAnimationFps{"fps", 12, {1, 60}};

std::optional<int> parse_image_size(const Query& q);
int parse_animation_fps(const Query& q);

// The tone curve of a turntable's 8-bit pictures unless the query's `tone_mapping` names another.
inline constexpr ToneCurve kTurntableToneCurve = ToneCurve::Neutral;
ToneMap parse_turntable_tone(const Query& q);

// The names of the 8-bit formats (is_eight_bit), in ImageFormat's order.
std::vector<std::string> eight_bit_format_names();
// `format` among those, default png.
ImageFormat parse_eight_bit_format(const Query& q);

}  // namespace lp::api
