// --auth-token-file: which files hold a usable token, and the comparison of tokens.
#include "server/http/bearer_auth.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/temp_dir.hpp"

namespace lp::server {
namespace {

std::filesystem::path write(const test::TempDir& dir, const std::string& text) {
  static int n = 0;
  const auto path = dir.path() / ("token" + std::to_string(n++));
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(BearerAuth, TokenFiles) {
  test::TempDir dir;
  const std::string hex = "0123456789abcdef0123456789abcdef";
  EXPECT_EQ(read_auth_token(write(dir, hex)), hex);
  EXPECT_EQ(read_auth_token(write(dir, hex + "\n")), hex);
  EXPECT_EQ(read_auth_token(write(dir, "  " + hex + "\r\n\n")), hex);
  EXPECT_EQ(read_auth_token(write(dir, "abc-._~+/ABCDEFGHIJ==")), "abc-._~+/ABCDEFGHIJ==");
  EXPECT_EQ(read_auth_token(write(dir, std::string(kMinAuthTokenLength, 'x'))),
            std::string(kMinAuthTokenLength, 'x'));
  for (const std::string& bad :
       {std::string(), std::string("\n"), std::string(kMinAuthTokenLength - 1, 'x'), hex + " " + hex,
        hex + "\n" + hex, "=" + hex, hex + "=x", hex + "\"", hex + ","})
    EXPECT_THROW(read_auth_token(write(dir, bad)), std::invalid_argument) << bad;
  try {
    read_auth_token(dir.path() / "absent");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--auth-token-file: cannot read"), std::string::npos) << e.what();
  }
}

TEST(BearerAuth, ConstantTimeEqualIsEquality) {
  const std::string token = "0123456789abcdef";
  EXPECT_TRUE(constant_time_equal(token, token));
  EXPECT_FALSE(constant_time_equal("", token));
  EXPECT_FALSE(constant_time_equal(token.substr(0, 15), token));
  EXPECT_FALSE(constant_time_equal(token + "0", token));
  EXPECT_FALSE(constant_time_equal(token + std::string(1, '\0'), token));
  EXPECT_FALSE(constant_time_equal("1123456789abcdef", token));
  EXPECT_FALSE(constant_time_equal("0123456789abcdee", token));
  EXPECT_TRUE(constant_time_equal("", ""));
}

TEST(BearerAuth, GuardedPaths) {
  for (const char* guarded : {"/api/v1/envmaps", "/api/v1/openapi.yaml", "/api/v1/nope", "/metrics"})
    EXPECT_TRUE(BearerAuth::guards(guarded)) << guarded;
  for (const char* open : {"/api/v1/health", "/api/v1/ready", "/", "/app.js", "/metrics/x"})
    EXPECT_FALSE(BearerAuth::guards(open)) << open;
}

}  // namespace
}  // namespace lp::server
