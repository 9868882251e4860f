#pragma once
// A sample set encoded piece by piece, so that memory stays bounded at any count: the JSON document of
// POST /envmaps/{id}/samples, its packed binary records, or CSV (a header naming the record's values,
// then one row per sample).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "api/sample_request.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp::api {

enum class SampleEncoding { JsonDocument, Binary, Csv };

class SampleStream {
 public:
  static constexpr uint64_t kChunk = 1 << 16;  // samples generated and encoded at a time

  SampleStream(std::shared_ptr<const EnvMapSampler> sampler, SampleRequest request, SampleEncoding encoding);

  // Appends the next piece (up to kChunk samples, with the document's start or end) to `out`; false once
  // everything was written. A set of at most kChunk samples comes whole in the first piece.
  bool next(std::string& out);

 private:
  std::shared_ptr<const EnvMapSampler> sampler_;
  std::shared_ptr<const AliasTable2D> alias_;  // independent sets: held (and reserved) from the start
  SampleRequest request_;
  SampleEncoding encoding_;
  std::vector<EnvSample> buffer_;
  uint64_t next_ = 0;
};

}  // namespace lp::api
