#include "framework/core/error.h"

#include <gtest/gtest.h>

namespace cooperage {

TEST(MeshingError, NamesTheEntityInWhat) {
  const MeshingError e(ErrorCode::NotApplicable, EntityRef::surface(12), "6 END vertices");
  EXPECT_STREQ(e.what(), "surface 12: 6 END vertices");
  EXPECT_EQ(e.message(), "6 END vertices");
  EXPECT_EQ(e.entity().dim, 2);
  EXPECT_EQ(e.entity().id, 12);
  EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
}

TEST(MeshingError, WithoutEntityIsJustTheMessage) {
  const MeshingError e(ErrorCode::FileNotFound, "part.step: no such file");
  EXPECT_STREQ(e.what(), "part.step: no such file");
  EXPECT_EQ(e.entity().name(), "");
}

TEST(EntityRef, NamesEveryDimension) {
  EXPECT_EQ(EntityRef::vertex(1).name(), "vertex 1");
  EXPECT_EQ(EntityRef::curve(2).name(), "curve 2");
  EXPECT_EQ(EntityRef::surface(3).name(), "surface 3");
  EXPECT_EQ(EntityRef::volume(4).name(), "volume 4");
}

TEST(ErrorCode, EveryCodeHasAName) {
  for (ErrorCode c : {ErrorCode::InvalidInput, ErrorCode::FileNotFound, ErrorCode::ParseError,
                      ErrorCode::GeometryError, ErrorCode::NotSupported, ErrorCode::NotApplicable,
                      ErrorCode::Infeasible, ErrorCode::MeshingFailed, ErrorCode::Internal}) {
    EXPECT_STRNE(to_string(c), "error");
  }
}

}  // namespace cooperage

namespace cooperage {

TEST(MeshingError, AHintSaysWhatToDoAndIsNotPartOfWhat) {
  const MeshingError e(ErrorCode::InvalidInput, EntityRef::volume(2), "the mesh would be too big",
                       "use a larger element size");
  EXPECT_STREQ(e.what(), "volume 2: the mesh would be too big");
  EXPECT_EQ(e.hint(), "use a larger element size");
  EXPECT_EQ(MeshingError(ErrorCode::InvalidInput, "x").hint(), "");
}

}  // namespace cooperage
