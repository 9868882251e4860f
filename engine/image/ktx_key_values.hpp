#pragma once
// The key/value data of KTX 1.1 and KTX 2.0 files, laid out alike: pairs of a 4-byte length, the key and
// its NUL, the value, padding to 4 bytes.
#include <cstdint>
#include <map>
#include <span>
#include <string>

namespace lp {

// The pairs of `data`; a value that ends in NUL (a string) without it. Throws lp::Error(Corrupt), its
// message starting with `format` ("KTX1"), for a pair that leaves the data, a key without its NUL or
// one given twice.
std::map<std::string, std::string> read_ktx_key_values(std::span<const uint8_t> data, const char* format);

}  // namespace lp
