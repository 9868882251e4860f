// Content hashes: SHA-256 against the test vectors of FIPS 180-2 (one block, two blocks, a million bytes
// fed in pieces and from a file of more than one read block), pieces that cannot run into each other, and
// a map's hash, which any one pixel or its size changes.
#include "server/storage/content_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "support/temp_dir.hpp"

namespace lp::server {
namespace {

TEST(ContentHash, IsSha256OfTheStandardsTestVectors) {
  EXPECT_EQ(content_hash(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(content_hash("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(content_hash("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  const std::string million(1'000'000, 'a');
  const std::string million_hash = "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0";
  EXPECT_EQ(content_hash(million), million_hash);
  ContentHasher pieces;
  for (int i = 0; i < 1000; ++i) pieces.add(std::string_view(million).substr(0, 1000));
  EXPECT_EQ(pieces.hex(), million_hash);
  EXPECT_TRUE(is_content_hash(million_hash));
}

TEST(ContentHash, OfAFileIsOfItsBytes) {
  test::TempDir dir;
  std::string bytes((3 << 20) + 17, '\0');  // more than one 1 MiB block
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 7919 % 251);
  std::ofstream(dir.path() / "f.bin", std::ios::binary) << bytes;
  EXPECT_EQ(file_content_hash(dir.path() / "f.bin"), content_hash(bytes));
  EXPECT_THROW(file_content_hash(dir.path() / "missing.bin"), std::runtime_error);
}

TEST(ContentHash, SizedPiecesCannotRunIntoEachOther) {
  EXPECT_NE(ContentHasher().add_sized("ab").add_sized("c").hex(),
            ContentHasher().add_sized("a").add_sized("bc").hex());
  EXPECT_EQ(ContentHasher().add("ab").add("c").hex(), content_hash("abc"));
}

TEST(ContentHash, HasOneForm) {
  EXPECT_TRUE(is_content_hash(std::string(64, 'f')));
  for (const std::string& bad :
       std::vector<std::string>{std::string(), std::string(63, 'f'), std::string(65, 'f'),
                                std::string(64, 'F'), std::string(63, 'f') + "g", std::string(16, '0')})
    EXPECT_FALSE(is_content_hash(bad)) << bad;
}

Image gradient(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, {float(x), float(y), 0.5f});
  return image;
}

TEST(EnvmapContentHash, IsTheSizeAndEveryPixel) {
  const std::string hash = envmap_content_hash(EnvMap(gradient(8, 4)));
  EXPECT_EQ(hash.size(), kContentHashHexDigits + 4);
  EXPECT_TRUE(is_content_hash(hash.substr(0, kContentHashHexDigits))) << hash;
  EXPECT_TRUE(hash.ends_with("-8x4")) << hash;
  EXPECT_EQ(envmap_content_hash(EnvMap(gradient(8, 4))), hash);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      Image one_other = gradient(8, 4);
      one_other.set(x, y, one_other.at(x, y) + Rgb{0, 0, 1e-6f});
      EXPECT_NE(envmap_content_hash(EnvMap(std::move(one_other))), hash) << x << ", " << y;
    }
  // The same floats in another shape: another map.
  const Image wide = gradient(8, 4);
  Image tall(4, 8);
  std::copy(wide.data().begin(), wide.data().end(), tall.data().begin());
  const std::string other_shape = envmap_content_hash(EnvMap(std::move(tall)));
  EXPECT_NE(other_shape.substr(0, kContentHashHexDigits), hash.substr(0, kContentHashHexDigits));
}

}  // namespace
}  // namespace lp::server
