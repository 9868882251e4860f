#include "api/sample_stream.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "api/sample_encoding.hpp"

namespace lp::api {
namespace {

std::string json_prologue(const SampleRequest& r) {
  return fmt::format(R"({{"count":{},"seed":{},"strategy":"{}","luminance":"{}","samples":[)", r.spec.count,
                     r.spec.seed, enum_name(r.spec.strategy), enum_name(r.luminance));
}

size_t bytes_per_sample(SampleEncoding encoding) {
  return encoding == SampleEncoding::Binary ? sizeof(float) * kSampleRecordFloats : 192;
}

}  // namespace

SampleStream::SampleStream(std::shared_ptr<const EnvMapSampler> sampler, SampleRequest request,
                           SampleEncoding encoding)
    : sampler_(std::move(sampler)), request_(std::move(request)), encoding_(encoding) {
  if (request_.spec.strategy == SampleStrategy::Independent) alias_ = sampler_->alias_table();
}

bool SampleStream::next(std::string& out) {
  const uint64_t total = request_.spec.count;
  if (next_ >= total) return false;
  if (next_ == 0 && encoding_ == SampleEncoding::JsonDocument) out += json_prologue(request_);
  if (next_ == 0 && encoding_ == SampleEncoding::Csv) out += std::string(kSampleRecordLayout) + "\n";
  const uint64_t n = std::min(kChunk, total - next_);
  buffer_.resize(n);
  generate_samples(*sampler_, request_.spec, next_, buffer_, alias_.get());
  out.reserve(out.size() + n * bytes_per_sample(encoding_));
  for (uint64_t k = 0; k < n; ++k) {
    switch (encoding_) {
      case SampleEncoding::JsonDocument:
        if (next_ + k > 0) out.push_back(',');
        append_sample_json(out, buffer_[k]);
        break;
      case SampleEncoding::Binary:
        append_sample_binary(out, buffer_[k]);
        break;
      case SampleEncoding::Csv:
        append_sample_csv(out, buffer_[k]);
        break;
    }
  }
  next_ += n;
  if (encoding_ == SampleEncoding::JsonDocument && next_ == total) out += "]}";
  return true;
}

}  // namespace lp::api
