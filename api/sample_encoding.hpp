#pragma once
// Wire encodings of samples: JSON objects, packed little-endian float32 records for large N, and CSV rows.
#include <string>

#include "api/sample_request.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp::api {

// {"pixel":[x,y],"uv":[u,v],"direction":[x,y,z],"theta":t,"phi":p,"pdf":q,"radiance":[r,g,b]}
void append_sample_json(std::string& out, const EnvSample& s);
// kSampleRecordFloats float32 values in the order of kSampleRecordLayout.
void append_sample_binary(std::string& out, const EnvSample& s);
// One CSV row (ending in a newline) of the values of a binary record, under the header kSampleRecordLayout.
void append_sample_csv(std::string& out, const EnvSample& s);

}  // namespace lp::api
