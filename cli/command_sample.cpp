// lightprobe sample MAP --count N: importance samples of a map, as POST /api/v1/envmaps/{id}/samples
// answers them (JSON or binary records), or as CSV.
#include <fmt/format.h>

#include "api/sample_stream.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"

namespace lp::cli {

enum class SampleFormat { Json, Csv, Bin };
constexpr auto enum_entries(SampleFormat) {
  return std::to_array<EnumEntry<SampleFormat>>(
      {{SampleFormat::Json, "json"}, {SampleFormat::Csv, "csv"}, {SampleFormat::Bin, "bin"}});
}

namespace {

constexpr std::string_view kSynopsis = "sample MAP --count N [options]";

api::SampleEncoding encoding(SampleFormat format) {
  switch (format) {
    case SampleFormat::Csv:
      return api::SampleEncoding::Csv;
    case SampleFormat::Bin:
      return api::SampleEncoding::Binary;
    case SampleFormat::Json:
      break;
  }
  return api::SampleEncoding::JsonDocument;
}

std::string help() {
  const api::RequestLimits limits;
  const api::SampleRequest d = api::parse_sample_request({{"count", 1}}, limits);
  return "Importance samples of the map, each with its pixel, direction, solid-angle pdf and radiance:\n"
         "the answer of POST /api/v1/envmaps/{id}/samples.\n\n" +
         option_line("--count N", fmt::format("samples, in [{}, {}] (required)", api::kSampleCount.range.min,
                                              limits.max_samples)) +
         option_line("--seed N", fmt::format("in [0, {}] (default {}): the same seed gives the same samples",
                                             api::kMaxSeed, d.spec.seed)) +
         option_line("--strategy NAME", choices(d.spec.strategy)) +
         option_line("--luminance NAME", choices(d.luminance)) + invalid_pixel_policy_help() +
         option_line("--format NAME",
                     choices(SampleFormat::Json) +
                         ": the API's JSON document, CSV with a header,\n"
                         "or the API's binary records: 13 little-endian float32 values each\n" +
                         api::kSampleRecordLayout) +
         output_help();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const SampleFormat format = args.take_enum("format", SampleFormat::Json);
  const auto file = args.take("output");
  const api::SampleRequest request =
      api::parse_sample_request(args.take_rest_as_json(), api::RequestLimits{});
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  api::SampleStream stream(loaded.map->sampler(request.luminance), request, encoding(format));
  Output out(file);
  for (std::string piece; stream.next(piece); piece.clear()) out.write(piece);
  if (format == SampleFormat::Json) out.write("\n");
  out.finish();
}

}  // namespace

Command sample_command() {
  return {"sample", kSynopsis, "importance samples of a map (JSON, CSV or binary records)", {}, help, run};
}

}  // namespace lp::cli
