#include "coinspect/core/hash.h"

#include <gtest/gtest.h>

#include <string>

namespace coinspect::core {
namespace {

// The published FNV-1a 64 values, and a hash continued piece by piece equals one over the whole.
TEST(Fnv1a, PublishedValuesAndContinuation) {
  EXPECT_EQ(fnv1a(nullptr, 0), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a", 1), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar", 6), 0x85944171f73967e8ull);
  EXPECT_EQ(fnv1a("bar", 3, fnv1a("foo", 3)), fnv1a("foobar", 6));
}

}  // namespace
}  // namespace coinspect::core
