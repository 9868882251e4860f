// JSON request bodies are parsed with their nesting bounded at kMaxJsonDepth levels: a deeper body is a
// 400 "json_too_deep" naming the limit, found while parsing (a 100,000-level body once overflowed the stack
// when an error message dumped it), and messages about bad values stay short whatever the value.
#include <gtest/gtest.h>

#include <string>

#include "api/api_error.hpp"
#include "api/params.hpp"
#include "api/sample_request.hpp"

namespace lp::api {
namespace {

std::string arrays(int depth) {
  return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
}

std::string objects(int depth) {
  std::string text;
  for (int i = 0; i < depth; ++i) text += R"({"a":)";
  text += "0";
  return text + std::string(size_t(depth), '}');
}

// The ApiError `body` gives, as "status code: message".
std::string rejection(const std::string& body) {
  try {
    parse_json_object(body);
  } catch (const ApiError& e) {
    return std::to_string(e.status()) + " " + std::string(code_name(e.code())) + ": " + e.what();
  }
  return "accepted";
}

TEST(JsonDepth, TheLimitItselfIsAccepted) {
  EXPECT_EQ(parse_json(arrays(kMaxJsonDepth)).size(), 1u);
  EXPECT_TRUE(parse_json(objects(kMaxJsonDepth)).is_object());
  // The body object is the first level: a field may hold kMaxJsonDepth - 1 levels more.
  EXPECT_EQ(rejection(R"({"count":)" + arrays(kMaxJsonDepth - 1) + "}"), "accepted");
}

TEST(JsonDepth, OneLevelMoreIsRefusedNamingTheLimit) {
  const std::string expected =
      "400 json_too_deep: the request body nests arrays and objects deeper than the "
      "limit of " +
      std::to_string(kMaxJsonDepth) + " levels";
  EXPECT_EQ(rejection(R"({"count":)" + arrays(kMaxJsonDepth) + "}"), expected);
  EXPECT_EQ(rejection(objects(kMaxJsonDepth + 1)), expected);
  EXPECT_THROW(parse_json(arrays(kMaxJsonDepth + 1)), ApiError);
}

TEST(JsonDepth, HundredThousandLevelsAreRefusedWithoutExhaustingTheStack) {
  EXPECT_EQ(rejection(R"({"count":)" + arrays(100'000) + "}").substr(0, 18), "400 json_too_deep:");
  EXPECT_EQ(rejection(objects(100'000)).substr(0, 18), "400 json_too_deep:");
  // Unclosed: refused at the limit, before the parser reaches the end and finds the syntax error.
  EXPECT_EQ(rejection(std::string(100'000, '[')).substr(0, 18), "400 json_too_deep:");
}

TEST(JsonDepth, OtherBadBodiesKeepTheirCodes) {
  EXPECT_EQ(rejection("{\"count\": "), "400 invalid_json: the request body is not valid JSON");
  EXPECT_EQ(rejection("[1]"), "400 invalid_json: the request body must be a JSON object");
}

// The message about a wrong value quotes at most a short excerpt of it.
std::string sample_rejection(const std::string& body) {
  try {
    RequestLimits limits;
    limits.max_samples = 1000;
    parse_sample_request(parse_json_object(body), limits);
  } catch (const ApiError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(JsonDepth, MessagesAboutHugeValuesStayShort) {
  const std::string huge(200'000, 'x');
  EXPECT_EQ(sample_rejection(R"({"count":")" + huge + R"("})"),
            "field 'count': must be an integer, got \"" + huge.substr(0, kExcerptBytes) + "...\"");
  EXPECT_EQ(sample_rejection(R"({"count":)" + arrays(kMaxJsonDepth - 1) + "}"),
            "field 'count': must be an integer, got an array of 1 item");
  EXPECT_EQ(sample_rejection(R"({"count":1,"strategy":")" + huge + R"("})"),
            "field 'strategy': '" + huge.substr(0, kExcerptBytes) +
                "...' is not one of: independent, stratified, sobol");
  // Found by tests/fuzz/sample_request on the parser that quoted the whole value (corpus:
  // long_seed_echoed.json).
  EXPECT_EQ(sample_rejection(R"({"count":4,"seed":")" + huge + R"("})"),
            "field 'seed': must be an integer, got \"" + huge.substr(0, kExcerptBytes) + "...\"");
  const std::string unknown = sample_rejection(R"({")" + huge + R"(":1})");
  EXPECT_EQ(unknown.find("field '" + huge.substr(0, kExcerptBytes) + "...': unknown field"), 0u);
  EXPECT_LT(unknown.size(), 200u);
}

}  // namespace
}  // namespace lp::api
