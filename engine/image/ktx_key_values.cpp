#include "engine/image/ktx_key_values.hpp"

#include <algorithm>
#include <cstring>

#include "engine/core/error.hpp"

namespace lp {

std::map<std::string, std::string> read_ktx_key_values(std::span<const uint8_t> data, const char* format) {
  const auto corrupt = [format](const char* what) {
    throw Error(ErrorKind::Corrupt, std::string(format) + ": " + what);
  };
  std::map<std::string, std::string> out;
  size_t at = 0;
  while (at < data.size()) {
    if (data.size() - at < 4) corrupt("a key/value length past the end of its section");
    uint32_t length;
    std::memcpy(&length, data.data() + at, 4);
    at += 4;
    if (length < 2 || length > data.size() - at) corrupt("a key/value pair past the end of its section");
    const std::string pair(reinterpret_cast<const char*>(data.data() + at), length);
    const size_t nul = pair.find('\0');
    if (nul == 0 || nul == std::string::npos) corrupt("a key without its NUL");
    std::string value = pair.substr(nul + 1);
    if (!value.empty() && value.back() == '\0') value.pop_back();
    if (!out.emplace(pair.substr(0, nul), std::move(value)).second) corrupt("a key given twice");
    at += (size_t(length) + 3) / 4 * 4;
  }
  if (at != data.size()) corrupt("key/value padding past the end of its section");
  return out;
}

}  // namespace lp
