// Request ids: which ids a client may give, the ids the server makes, and api/openapi.yaml's schema of
// them agreeing with both.
#include "server/http/request_id.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <regex>
#include <set>
#include <string>

#include "api/openapi.hpp"

namespace lp::server {
namespace {

const std::vector<std::string>& examples() {
  static const std::vector<std::string> ids = {"9f86d081884c7d65",
                                               "3fa85f64-5717-4562-b3fc-2c963f66afa6",
                                               "00-4bf92f3577b34da6a3ce929d0e0e4736-00f067aa0ba902b7-01",
                                               "req_1.2:3",
                                               std::string(kMaxRequestIdLength, 'a'),
                                               "",
                                               std::string(kMaxRequestIdLength + 1, 'a'),
                                               "a b",
                                               "a\"b",
                                               "a\\nb",
                                               "a/b",
                                               "caf\xc3\xa9",
                                               "<script>"};
  return ids;
}

TEST(RequestId, SafeIdsAreKeptOthersReplaced) {
  for (size_t i = 0; i < examples().size(); ++i) EXPECT_EQ(is_safe_request_id(examples()[i]), i < 5) << i;
}

TEST(RequestId, NewIdsAreSixteenHexDigitsAndDiffer) {
  std::set<std::string> seen;
  for (int i = 0; i < 1000; ++i) {
    const std::string id = new_request_id();
    EXPECT_TRUE(std::regex_match(id, std::regex("[0-9a-f]{16}"))) << id;
    EXPECT_TRUE(is_safe_request_id(id));
    seen.insert(id);
  }
  EXPECT_EQ(seen.size(), 1000u);
}

TEST(RequestId, TheOpenApiSchemaIsTheSameRule) {
  const YAML::Node doc = YAML::Load(std::string(api::openapi_document()));
  const YAML::Node schema = doc["components"]["schemas"]["RequestId"];
  ASSERT_TRUE(schema);
  EXPECT_EQ(schema["maxLength"].as<size_t>(), kMaxRequestIdLength);
  EXPECT_EQ(schema["minLength"].as<size_t>(), 1u);
  const std::regex pattern(schema["pattern"].as<std::string>());
  for (const std::string& id : examples()) {
    const bool documented =
        id.size() >= 1 && id.size() <= kMaxRequestIdLength && std::regex_search(id, pattern);
    EXPECT_EQ(documented, is_safe_request_id(id)) << id;
  }
  EXPECT_EQ(doc["components"]["schemas"]["Error"]["properties"]["error"]["properties"]["request_id"]["$ref"]
                .as<std::string>(),
            "#/components/schemas/RequestId");
}

}  // namespace
}  // namespace lp::server
