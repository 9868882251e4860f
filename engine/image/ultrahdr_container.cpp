#include "engine/image/ultrahdr_container.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

#include "engine/core/error.hpp"

namespace lp::ultrahdr {
namespace {

constexpr std::string_view kXmpNamespace{"http://ns.adobe.com/xap/1.0/\0", 29};
constexpr std::string_view kMpfSignature{"MPF\0", 4};
constexpr uint16_t kTagMpfVersion = 0xB000, kTagImageCount = 0xB001, kTagMpEntry = 0xB002;
constexpr uint16_t kTypeLong = 4, kTypeUndefined = 7;
constexpr uint32_t kPrimaryAttribute = 0x00030000;  // baseline MP primary image, JPEG
constexpr size_t kEntryBytes = 16;

[[noreturn]] void corrupt(const std::string& why) {
  throw Error(ErrorKind::Corrupt, "corrupt Ultra HDR JPEG: " + why);
}

void put16(std::vector<uint8_t>& out, uint32_t v) {
  out.push_back(uint8_t(v >> 8));
  out.push_back(uint8_t(v));
}
void put32(std::vector<uint8_t>& out, uint32_t v) {
  put16(out, v >> 16);
  put16(out, v & 0xFFFF);
}
void put_text(std::vector<uint8_t>& out, std::string_view s) {
  out.insert(out.end(), s.begin(), s.end());
}

std::vector<uint8_t> xmp_segment(std::string packet) {
  // three.js's UltraHDRLoader parses the segment from its first '<' to its last '>', length bytes
  // included: pad the packet until neither length byte is one of them.
  const auto bad = [](size_t n) { return n == '<' || n == '>'; };
  for (size_t length = 2 + kXmpNamespace.size() + packet.size(); bad(length >> 8) || bad(length & 0xFF);
       ++length)
    packet += ' ';
  std::vector<uint8_t> payload;
  put_text(payload, kXmpNamespace);
  put_text(payload, packet);
  return app_segment(1, payload);
}

std::string xmp_packet(std::string_view description) {
  return fmt::format(
      "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\" x:xmptk=\"Lightprobe\">"
      "<rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">{}</rdf:RDF></x:xmpmeta>",
      description);
}

// Big- or little-endian reads within one span; any read past its end is corrupt data.
class Reader {
 public:
  Reader(std::span<const uint8_t> b, bool big_endian) : b_(b), big_(big_endian) {}
  uint32_t u16(size_t at) const {
    check(at, 2);
    return big_ ? uint32_t(b_[at] << 8 | b_[at + 1]) : uint32_t(b_[at + 1] << 8 | b_[at]);
  }
  uint32_t u32(size_t at) const {
    return big_ ? (u16(at) << 16 | u16(at + 2)) : (u16(at + 2) << 16 | u16(at));
  }

 private:
  void check(size_t at, size_t n) const {
    if (at > b_.size() || b_.size() - at < n) corrupt("MPF index ends early");
  }
  std::span<const uint8_t> b_;
  bool big_;
};

struct Segment {
  int marker = 0;
  std::span<const uint8_t> payload;
};

// The marker segments of a JPEG from SOI to its first SOS (where the metadata ends).
std::vector<Segment> header_segments(std::span<const uint8_t> jpeg, const char* which) {
  if (jpeg.size() < 4 || jpeg[0] != 0xFF || jpeg[1] != 0xD8)
    corrupt(fmt::format("{} image has no SOI", which));
  std::vector<Segment> segments;
  size_t at = 2;
  while (true) {
    if (jpeg.size() - at < 4 || jpeg[at] != 0xFF)
      corrupt(fmt::format("{} image ends before its scan", which));
    const int marker = jpeg[at + 1];
    const size_t length = size_t(jpeg[at + 2]) << 8 | jpeg[at + 3];
    if (length < 2 || jpeg.size() - at - 2 < length)
      corrupt(fmt::format("{} image has a truncated segment", which));
    segments.push_back({marker, jpeg.subspan(at + 4, length - 2)});
    if (marker == 0xDA) return segments;
    at += 2 + length;
  }
}

bool starts_with(std::span<const uint8_t> b, std::string_view prefix) {
  return b.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), b.begin());
}

// The gain map's offset and size from an MPF payload (after "MPF\0").
std::pair<uint32_t, uint32_t> gain_map_entry(std::span<const uint8_t> tiff) {
  if (tiff.size() < 8) corrupt("MPF index ends early");
  const bool big = tiff[0] == 'M' && tiff[1] == 'M';
  if (!big && !(tiff[0] == 'I' && tiff[1] == 'I')) corrupt("MPF index has no byte order mark");
  const Reader r(tiff, big);
  const size_t ifd = r.u32(4);
  const uint32_t tags = r.u16(ifd);
  for (uint32_t i = 0; i < tags; ++i) {
    const size_t tag = ifd + 2 + size_t(i) * 12;
    if (r.u16(tag) != kTagMpEntry) continue;
    if (r.u32(tag + 4) < 2 * kEntryBytes) corrupt("MPF index lists fewer than two images");
    const size_t second = size_t(r.u32(tag + 8)) + kEntryBytes;
    return {r.u32(second + 8), r.u32(second + 4)};
  }
  corrupt("MPF index has no MP entry tag");
}

std::optional<std::string_view> attribute(std::string_view xmp, std::string_view name) {
  const std::string key = fmt::format("hdrgm:{}=\"", name);
  const size_t start = xmp.find(key);
  if (start == std::string_view::npos) return std::nullopt;
  const size_t begin = start + key.size(), end = xmp.find('"', begin);
  if (end == std::string_view::npos) corrupt(fmt::format("hdrgm:{} has no closing quote", name));
  return xmp.substr(begin, end - begin);
}

double number(std::string_view xmp, std::string_view name, std::optional<double> fallback) {
  const auto text = attribute(xmp, name);
  if (!text) {
    if (!fallback) corrupt(fmt::format("gain map XMP has no hdrgm:{}", name));
    return *fallback;
  }
  double v = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size() || !std::isfinite(v))
    corrupt(fmt::format("hdrgm:{} is not a number", name));
  return v;
}

GainMapParams parse_params(std::string_view xmp) {
  if (attribute(xmp, "Version") != "1.0") corrupt("gain map XMP is not hdrgm version 1.0");
  if (attribute(xmp, "BaseRenditionIsHDR").value_or("False") != "False")
    corrupt("an HDR base rendition is not supported");
  const GainMapParams d;
  GainMapParams p;
  p.gain_map_min = number(xmp, "GainMapMin", d.gain_map_min);
  p.gain_map_max = number(xmp, "GainMapMax", std::nullopt);
  p.gamma = number(xmp, "Gamma", d.gamma);
  p.offset_sdr = number(xmp, "OffsetSDR", d.offset_sdr);
  p.offset_hdr = number(xmp, "OffsetHDR", d.offset_hdr);
  p.hdr_capacity_min = number(xmp, "HDRCapacityMin", d.hdr_capacity_min);
  p.hdr_capacity_max = number(xmp, "HDRCapacityMax", std::nullopt);
  if (!(p.gain_map_max >= p.gain_map_min) || !(p.gamma > 0) || std::abs(p.gain_map_min) > 64 ||
      std::abs(p.gain_map_max) > 64 || p.offset_sdr < 0 || p.offset_hdr < 0)
    corrupt("gain map parameters out of range");
  return p;
}

}  // namespace

std::vector<uint8_t> app_segment(int n, std::span<const uint8_t> payload) {
  if (payload.size() + 2 > 0xFFFF) throw Error(ErrorKind::Internal, "JPEG segment over 64 KiB");
  std::vector<uint8_t> out{0xFF, uint8_t(0xE0 + n)};
  put16(out, uint32_t(payload.size() + 2));
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::vector<uint8_t> primary_xmp_segment(size_t gain_map_bytes) {
  return xmp_segment(xmp_packet(fmt::format(
      "<rdf:Description rdf:about=\"\" xmlns:Container=\"http://ns.google.com/photos/1.0/container/\" "
      "xmlns:Item=\"http://ns.google.com/photos/1.0/container/item/\" "
      "xmlns:hdrgm=\"http://ns.adobe.com/hdr-gain-map/1.0/\" hdrgm:Version=\"1.0\">"
      "<Container:Directory><rdf:Seq>"
      "<rdf:li rdf:parseType=\"Resource\"><Container:Item Item:Semantic=\"Primary\" "
      "Item:Mime=\"image/jpeg\"/>"
      "</rdf:li><rdf:li rdf:parseType=\"Resource\"><Container:Item Item:Semantic=\"GainMap\" "
      "Item:Mime=\"image/jpeg\" Item:Length=\"{}\"/></rdf:li>"
      "</rdf:Seq></Container:Directory></rdf:Description>",
      gain_map_bytes)));
}

std::vector<uint8_t> gain_map_xmp_segment(const GainMapParams& p) {
  return xmp_segment(xmp_packet(fmt::format(
      "<rdf:Description rdf:about=\"\" xmlns:hdrgm=\"http://ns.adobe.com/hdr-gain-map/1.0/\" "
      "hdrgm:Version=\"1.0\" hdrgm:GainMapMin=\"{}\" hdrgm:GainMapMax=\"{}\" hdrgm:Gamma=\"{}\" "
      "hdrgm:OffsetSDR=\"{}\" hdrgm:OffsetHDR=\"{}\" hdrgm:HDRCapacityMin=\"{}\" hdrgm:HDRCapacityMax=\"{}\" "
      "hdrgm:BaseRenditionIsHDR=\"False\"/>",
      p.gain_map_min, p.gain_map_max, p.gamma, p.offset_sdr, p.offset_hdr, p.hdr_capacity_min,
      p.hdr_capacity_max)));
}

std::vector<uint8_t> mpf_segment(uint32_t primary_bytes, uint32_t gain_map_bytes, uint32_t gain_map_offset) {
  constexpr uint32_t kTags = 3, kIfd = 8, kEntries = kIfd + 2 + kTags * 12 + 4;
  std::vector<uint8_t> p;
  put_text(p, kMpfSignature);
  put_text(p, "MM");
  put16(p, 0x2A);
  put32(p, kIfd);
  put16(p, kTags);
  put16(p, kTagMpfVersion), put16(p, kTypeUndefined), put32(p, 4), put_text(p, "0100");
  put16(p, kTagImageCount), put16(p, kTypeLong), put32(p, 1), put32(p, 2);
  put16(p, kTagMpEntry), put16(p, kTypeUndefined), put32(p, 2 * kEntryBytes), put32(p, kEntries);
  put32(p, 0);  // no next IFD
  put32(p, kPrimaryAttribute), put32(p, primary_bytes), put32(p, 0), put32(p, 0);
  put32(p, 0), put32(p, gain_map_bytes), put32(p, gain_map_offset), put32(p, 0);
  return app_segment(2, p);
}

Parts split(std::span<const uint8_t> file) {
  std::optional<std::pair<uint32_t, uint32_t>> entry;  // offset, size
  size_t tiff_at = 0;
  for (const Segment& s : header_segments(file, "primary")) {
    if (s.marker != 0xE2 || !starts_with(s.payload, kMpfSignature)) continue;
    tiff_at = size_t(s.payload.data() - file.data()) + kMpfSignature.size();
    entry = gain_map_entry(s.payload.subspan(kMpfSignature.size()));
    break;
  }
  if (!entry) corrupt("primary image has no MPF index");
  const auto [offset, size] = *entry;
  if (offset > file.size() - tiff_at || size > file.size() - tiff_at - offset)
    corrupt("MPF index places the gain map outside the file");
  Parts parts;
  parts.primary = file.first(tiff_at + offset);
  parts.gain_map = file.subspan(tiff_at + offset, size);
  for (const Segment& s : header_segments(parts.gain_map, "gain map")) {
    if (s.marker != 0xE1 || !starts_with(s.payload, kXmpNamespace)) continue;
    const auto xmp = s.payload.subspan(kXmpNamespace.size());
    parts.params = parse_params({reinterpret_cast<const char*>(xmp.data()), xmp.size()});
    return parts;
  }
  corrupt("gain map has no hdrgm XMP");
}

}  // namespace lp::ultrahdr
