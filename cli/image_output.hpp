#pragma once
// The image a command writes, chosen by the API's image parameters (format, exposure, gamma, tone mapping;
// see api/preview_params.hpp): --format, else the output file's extension (.exr, .pfm, .hdr, .png), else png.
#include <optional>
#include <string>

#include "api/preview_params.hpp"
#include "cli/arguments.hpp"

namespace lp::cli {

// The format a file name's extension names (.exr, .pfm, .hdr, .png, any case), if it names one.
std::optional<ImageFormat> image_format_of_name(const std::string& file);

// Where the tone curve of an 8-bit picture comes from: --tone-mapping (default standard), or a render
// request, whose top-level `tone_mapping` field (default neutral) --tone-mapping sets as it sets the others.
enum class ToneOption { Own, RequestField };

// Takes --format, --exposure, --gamma and, with ToneOption::Own, --tone-mapping. Throws bad_request when
// neither --format nor the extension of `file` names a format.
api::PreviewParams take_image_params(Arguments& args, const std::optional<std::string>& file,
                                     ToneOption tone = ToneOption::Own);

// The help lines of those options.
std::string image_params_help(ToneOption tone = ToneOption::Own);

}  // namespace lp::cli
