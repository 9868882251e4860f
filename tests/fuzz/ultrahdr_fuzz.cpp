// The Ultra HDR decoder (container, XMP, MPF index, both JPEGs) on any bytes.
// fuzz-max-len: 8192
#include "decoder_fuzz.hpp"
#include "engine/image/ultrahdr.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lp::fuzz::decode(data, size, lp::decode_ultrahdr);
}
