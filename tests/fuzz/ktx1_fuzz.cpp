// The KTX 1.1 reader alone, on any bytes.
#include "decoder_fuzz.hpp"
#include "engine/image/ktx1.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lp::fuzz::decode(data, size, lp::read_ktx1);
}
