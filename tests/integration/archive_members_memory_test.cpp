// A zip of 200,000 tiny members uploaded as an asset (--max-asset-files 1000) on the real server: its
// 413 comes before libarchive reads the central directory into memory, so the server's peak resident
// memory grows by little more than the upload itself.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "support/archive_builder.hpp"
#include "support/http_reply.hpp"
#include "support/process_status.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using test::Reply;

constexpr int kMembers = 200000;

// Members with short names and no bytes: little upload for each entry of the central directory.
std::string many_members_zip() {
  std::vector<test::ArchiveMember> members;
  for (int i = 0; i < kMembers; ++i) members.push_back(test::file_member(std::to_string(i), ""));
  return test::make_archive(test::ArchiveFormat::Zip, members);
}

TEST(ArchiveMembersMemory, AZipOfManyMembersIsRefusedBeforeItsDirectoryIsRead) {
  const std::string zip = many_members_zip();
  test::ServerProcess s;
  const auto client = s.client();
  const double before = test::peak_rss_mib(s.pid());
  const auto start = std::chrono::steady_clock::now();
  const Reply r = test::reply(client->Post("/api/v1/assets?name=crowd", zip, "application/octet-stream"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double after = test::peak_rss_mib(s.pid());
  EXPECT_EQ(r.status, 413) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "too_large");
  EXPECT_NE(r.body.find("more than 1000 members (--max-asset-files)"), std::string::npos) << r.body;
  const double upload_mib = double(zip.size()) / (1 << 20);
  std::printf("upload %.1f MiB of %d members: 413 after %.2f s, VmHWM %.1f -> %.1f MiB\n", upload_mib,
              kMembers, seconds, before, after);
  // The body is held while it is read and checked, with the transport's buffers; the directory's
  // entries are not (libarchive takes about as much again for them).
  EXPECT_LT(after - before, upload_mib + 12) << "growth of the server's peak resident memory in MiB";
  EXPECT_TRUE(s.alive());
}

}  // namespace
}  // namespace lp
