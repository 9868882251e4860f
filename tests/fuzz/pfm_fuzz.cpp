// The PFM decoder alone, on any bytes.
#include "decoder_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lp::fuzz::decode(data, size, lp::read_pfm);
}
