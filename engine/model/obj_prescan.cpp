#include "engine/model/obj_prescan.hpp"

#include <fmt/format.h>

#include <charconv>
#include <climits>
#include <vector>

#include "engine/core/error.hpp"

namespace lp::obj {
namespace {

struct Line {
  std::string_view keyword;
  std::vector<std::string_view> tokens;
};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Whitespace-separated tokens. '#' starts a comment only as the first token, as for the library (which
// parses numbers after a '#' later in a line).
Line split(std::string_view text) {
  Line line;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    const size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    if (i == start) continue;
    const std::string_view token = text.substr(start, i - start);
    if (line.keyword.empty())
      line.keyword = token;
    else
      line.tokens.push_back(token);
  }
  return line;
}

class Checker {
 public:
  Checker(const std::string& name, int64_t max_triangles) : name_(name), max_triangles_(max_triangles) {}

  int64_t triangles() const { return triangles_; }

  // A material library line: numbers and texture options, checked wherever they are.
  void mtl_line(size_t number, std::string_view text) {
    line_ = number;
    const Line l = split(text);
    if (l.keyword.empty() || l.keyword[0] == '#' || l.keyword == "newmtl") return;
    for (std::string_view t : l.tokens) {
      integers_fit(t);
      number_prefix(t);  // the library parses a number wherever it expects one, whatever follows it
    }
  }

  void line(size_t number, std::string_view text) {
    line_ = number;
    const Line l = split(text);
    const std::string_view k = l.keyword;
    if (k.empty() || k[0] == '#' || k == "o" || k == "g" || k == "usemtl" || k == "mtllib") return;
    for (std::string_view t : l.tokens) integers_fit(t);
    if (k == "v" || k == "vn" || k == "vt") {
      for (std::string_view t : l.tokens) real(t);
    } else if (k == "vw") {
      skin_weights(l.tokens);
    } else if (k == "f" || k == "l" || k == "p") {
      for (std::string_view t : l.tokens) vertex_reference(t);
      if (k == "f") face(l.tokens.size());
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(ErrorKind::Corrupt, fmt::format("mesh {} line {}: {}", name_, line_, why));
  }

  // Every run of digits that atoi could read (at the start of a token or of a '/' field) fits an int.
  void integers_fit(std::string_view token) const {
    for (size_t start = 0; start <= token.size();) {
      const size_t end = std::min(token.find('/', start), token.size());
      std::string_view field = token.substr(start, end - start);
      if (!field.empty() && (field[0] == '+' || field[0] == '-')) field.remove_prefix(1);
      size_t digits = 0;
      while (digits < field.size() && is_digit(field[digits])) ++digits;
      int64_t value = 0;
      if (digits &&
          (digits > 10 || (std::from_chars(field.data(), field.data() + digits, value), value > INT_MAX)))
        fail(fmt::format("'{}' is out of the range of an integer", token.substr(0, 32)));
      start = end + 1;
    }
  }

  // The length of the number [sign] digits [. digits] [e [sign] digits] that `t` starts with (0 if
  // none); an exponent must have 1 to kMaxObjExponentDigits digits.
  size_t number_prefix(std::string_view t) const {
    size_t i = 0, mantissa = 0;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    while (i < t.size() && is_digit(t[i])) ++i, ++mantissa;
    if (i < t.size() && t[i] == '.') ++i;
    while (i < t.size() && is_digit(t[i])) ++i, ++mantissa;
    if (mantissa == 0) return 0;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
      ++i;
      if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
      size_t exponent = 0;
      while (i < t.size() && is_digit(t[i])) ++i, ++exponent;
      if (exponent == 0 || exponent > size_t(kMaxObjExponentDigits))
        fail(fmt::format("'{}' has an exponent of over {} digits", t.substr(0, 32), kMaxObjExponentDigits));
    }
    return i;
  }

  void real(std::string_view t) const {
    if (number_prefix(t) != t.size()) fail(fmt::format("'{}' is not a number", t.substr(0, 32)));
  }

  // vw vertex (joint weight)*: joint ids are whole numbers the library converts through a float.
  void skin_weights(const std::vector<std::string_view>& tokens) const {
    if (tokens.empty() || tokens.size() % 2 != 1) fail("vw needs a vertex and (joint, weight) pairs");
    for (size_t i = 1; i < tokens.size(); i += 2) {
      int64_t joint = -1;
      const auto t = tokens[i];
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), joint);
      if (ec != std::errc() || end != t.data() + t.size() || joint < 0 || joint > kMaxObjJointId)
        fail(
            fmt::format("joint id '{}' is not a whole number from 0 to {}", t.substr(0, 32), kMaxObjJointId));
      real(tokens[i + 1]);
    }
  }

  // v, v/vt, v//vn or v/vt/vn: each present index a non-zero integer.
  void vertex_reference(std::string_view token) const {
    int fields = 0;
    for (size_t start = 0; start <= token.size(); ++fields) {
      const size_t end = std::min(token.find('/', start), token.size());
      const std::string_view field = token.substr(start, end - start);
      int index = 0;
      const auto [ptr, ec] = std::from_chars(field.data() + (field.starts_with('+') ? 1 : 0),
                                             field.data() + field.size(), index);
      if ((fields == 0 || !field.empty()) &&
          (ec != std::errc() || ptr != field.data() + field.size() || index == 0))
        fail(fmt::format("'{}' is not a vertex reference", token.substr(0, 32)));
      start = end + 1;
    }
    if (fields > 3) fail(fmt::format("'{}' is not a vertex reference", token.substr(0, 32)));
  }

  void face(size_t vertices) {
    if (vertices > size_t(kMaxObjFaceVertices))
      fail(fmt::format("a face of {} vertices (the most is {})", vertices, kMaxObjFaceVertices));
    if (vertices >= 3) triangles_ += int64_t(vertices) - 2;
    if (triangles_ > max_triangles_)
      throw Error(ErrorKind::TooLarge, fmt::format("mesh {} has over {} triangles", name_, max_triangles_));
  }

  const std::string& name_;
  int64_t max_triangles_;
  size_t line_ = 0;
  int64_t triangles_ = 0;
};

// Calls line(number, text) for each line. Lines end at '\n', '\r' or "\r\n", as the library reads them.
template <class Line>
void for_each_line(std::string_view text, Line&& line) {
  size_t number = 0;
  for (size_t start = 0; start < text.size();) {
    const size_t end = std::min(text.find_first_of("\r\n", start), text.size());
    line(++number, text.substr(start, end - start));
    start = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
  }
}

}  // namespace

int64_t check_obj_text(std::string_view text, const std::string& name, int64_t max_triangles) {
  Checker checker(name, max_triangles);
  for_each_line(text, [&](size_t number, std::string_view line) { checker.line(number, line); });
  return checker.triangles();
}

void check_mtl_text(std::string_view text, const std::string& name) {
  Checker checker(name, 0);
  for_each_line(text, [&](size_t number, std::string_view line) { checker.mtl_line(number, line); });
}

}  // namespace lp::obj
