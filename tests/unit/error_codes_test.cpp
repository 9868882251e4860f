// The error-code table: one row per code, each engine ErrorKind answered by exactly one code, and the
// codes api/openapi.yaml lists are the table's.
#include "api/error_codes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "api/openapi_error_codes.hpp"

namespace lp::api {
namespace {

TEST(ErrorCodes, TheDocumentListsExactlyTheTablesCodes) {
  std::vector<std::string> table;
  for (const auto& entry : error_code_table()) table.emplace_back(entry.name);
  EXPECT_EQ(documented_error_codes(), table);
}

TEST(ErrorCodes, NamesAreUniqueAndStatusesAreErrors) {
  std::set<std::string_view> names;
  for (const auto& entry : error_code_table()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    EXPECT_GE(entry.status, 400) << entry.name;
    EXPECT_LE(entry.status, 599) << entry.name;
    EXPECT_EQ(http_status(entry.code), entry.status);
    EXPECT_EQ(code_name(entry.code), entry.name);
  }
}

TEST(ErrorCodes, EveryEngineErrorKindHasItsOwnCode) {
  const std::vector<ErrorKind> kinds = {
      ErrorKind::InvalidArgument, ErrorKind::Unsupported, ErrorKind::Corrupt,     ErrorKind::InvalidData,
      ErrorKind::TooLarge,        ErrorKind::NotFound,    ErrorKind::WriteFailed, ErrorKind::Internal};
  std::set<ErrorCode> codes;
  for (const ErrorKind kind : kinds) {
    const ErrorCode code = error_code_for(kind);
    EXPECT_EQ(error_code_table()[size_t(code)].kind, kind);
    codes.insert(code);
  }
  EXPECT_EQ(codes.size(), kinds.size());
}

TEST(ErrorCodes, TheFixedDisagreements) {
  EXPECT_EQ(code_name(error_code_for(ErrorKind::Corrupt)), "corrupt");
  EXPECT_EQ(http_status(error_code_for(ErrorKind::Corrupt)), 422);
  EXPECT_EQ(code_name(error_code_for(ErrorKind::WriteFailed)), "write_failed");
  EXPECT_EQ(http_status(error_code_for(ErrorKind::WriteFailed)), 500);
  EXPECT_EQ(http_status(error_code_for(ErrorKind::Internal)), 500);
  EXPECT_EQ(http_status(error_code_for(ErrorKind::NotFound)), 404);
}

}  // namespace
}  // namespace lp::api
