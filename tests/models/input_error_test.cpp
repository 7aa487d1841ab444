// The bad-input error: its message names the place and the key, and the bare message can be
// re-thrown with another place without repeating either.
#include <gtest/gtest.h>

#include <string>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// The shown text puts the place and the key before what was wrong.
TEST(InputError, NamesThePlaceThenTheKey) {
  const InputError e("case.toml:3", "hopper.outlet_width", "expected a length, e.g. \"60 mm\"");
  EXPECT_STREQ(e.what(), "case.toml:3: hopper.outlet_width: expected a length, e.g. \"60 mm\"");
  EXPECT_EQ(e.message(), "expected a length, e.g. \"60 mm\"");
}

// Re-thrown with a file added, the key appears once and the message is unchanged, even when the
// message itself starts with the key's text.
TEST(InputError, RethrownWithAPlaceKeepsTheMessageWhole) {
  const InputError inner("", "dem.slab_faces", "dem.slab_faces: planar needs one layer");
  const InputError outer("pilot.toml", inner.key(), inner.message());
  EXPECT_STREQ(outer.what(), "pilot.toml: dem.slab_faces: dem.slab_faces: planar needs one layer");
  EXPECT_EQ(outer.message(), inner.message());
}

}  // namespace
}  // namespace feedflow
