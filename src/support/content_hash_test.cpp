#include "duet/support/content_hash.hpp"

#include <gtest/gtest.h>

namespace duet {
namespace {

// FNV-1a's published 64-bit values.
TEST(ContentHash, IsFnv1aOf64Bits) {
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "85944171f73967e8");
}

}  // namespace
}  // namespace duet
