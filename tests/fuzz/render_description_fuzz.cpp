// The render description a worker reads from Redis (server/scale_out/render_description.hpp), on any text:
// std::invalid_argument is a clean refusal; a parsed description names bundles only by bundle hashes
// and writes back to text that parses to the same description.
// fuzz-dictionary: json.dict
#include <cstdlib>
#include <stdexcept>

#include "fuzz_input.hpp"
#include "server/scale_out/bundle_hash.hpp"
#include "server/scale_out/render_description.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto d = lp::server::parse_description(lp::fuzz::as_text(data, size));
    for (const auto& m : d.meshes)
      if (!lp::server::is_bundle_hash(m.bundle)) std::abort();
    const auto again = lp::server::parse_description(lp::server::description_json(d));
    if (again.request != d.request || again.envmap_hash != d.envmap_hash ||
        again.source_url != d.source_url || again.meshes.size() != d.meshes.size())
      std::abort();
    for (size_t i = 0; i < d.meshes.size(); ++i)
      if (again.meshes[i].object != d.meshes[i].object || again.meshes[i].bundle != d.meshes[i].bundle ||
          again.meshes[i].model != d.meshes[i].model)
        std::abort();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
