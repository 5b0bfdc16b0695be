// The registry: names, origins, roles, and the best scheme of a role.
#include "framework/scheme/registry.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <memory>

namespace cooperage::scheme {
namespace {

// A surface scheme with a fixed answer, for ranking tests.
class Fixed final : public SurfaceScheme {
 public:
  Fixed(std::string name, Role roles, bool ok, double score)
      : name_(std::move(name)), roles_(roles), ok_(ok), score_(score) {}
  std::string_view name() const override { return name_; }
  Role serves() const override { return roles_; }
  Applicability applicable(const SurfaceView&) const override {
    return ok_ ? Applicability::yes(score_, name_ + " fits")
               : Applicability::no(name_ + " does not");
  }
  void constrain(const SurfaceView&, intervals::IntervalProblem&) const override {}
  EntityMesh mesh(const SurfaceView&, const MeshParams&) const override { return {}; }

 private:
  std::string name_;
  Role roles_;
  bool ok_;
  double score_;
};

const geom::Model& empty_model() {
  static const geom::Model model;
  return model;
}

TEST(Role, FlagsCombineAndPrint) {
  const Role r = Role::QuadCap | Role::SweepSide;
  EXPECT_TRUE(serves(r, Role::QuadCap));
  EXPECT_TRUE(serves(r, Role::SweepSide));
  EXPECT_FALSE(serves(r, Role::TriCap));
  EXPECT_FALSE(serves(r, Role::None));
  EXPECT_EQ(to_string(r), "quad cap, sweep side");
  EXPECT_EQ(to_string(Role::None), "none");
}

TEST(Registry, OriginIsBuiltInOutsideAScopeAndTheLibraryInside) {
  Registry r;
  r.add(std::make_unique<Fixed>("a", Role::QuadCap, true, 0.5));
  {
    const Registry::OriginScope scope(r, "/lib/libx.so");
    r.add(std::make_unique<Fixed>("b", Role::QuadCap, true, 0.5));
  }
  r.add(std::make_unique<Fixed>("c", Role::None, true, 0.5));
  EXPECT_EQ(r.origin(2, "a"), Registry::kBuiltIn);
  EXPECT_EQ(r.origin(2, "b"), "/lib/libx.so");
  EXPECT_EQ(r.origin(2, "c"), Registry::kBuiltIn);
  EXPECT_EQ(r.origin(2, "d"), "");
  EXPECT_EQ(r.origin(3, "a"), "");  // names are per dimension
  EXPECT_TRUE(r.has_library("/lib/libx.so"));
  EXPECT_FALSE(r.has_library("/lib/liby.so"));
  EXPECT_EQ(r.names(2), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_TRUE(r.names(3).empty());
}

TEST(Registry, ADuplicateNameNamesBothOrigins) {
  Registry r;
  r.add(std::make_unique<Fixed>("pave", Role::QuadCap, true, 0.6));
  const Registry::OriginScope scope(r, "/p/libdup.so");
  try {
    r.add(std::make_unique<Fixed>("pave", Role::QuadCap, true, 0.6));
    FAIL() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(e.message().find("\"pave\" from /p/libdup.so is already registered (built in)"),
              std::string::npos)
        << e.message();
  }
}

TEST(Registry, RejectsNamesAJournalCouldNotPin) {
  for (const char* bad : {"", "auto", "two words", "a/b", "(volume)"}) {
    Registry r;
    EXPECT_THROW(r.add(std::make_unique<Fixed>(bad, Role::None, true, 1)), MeshingError) << bad;
  }
  Registry r;
  EXPECT_NO_THROW(r.add(std::make_unique<Fixed>("my-scheme.v2_b", Role::None, true, 1)));
}

TEST(Registry, SchemesOfARoleInRegistrationOrder) {
  Registry r;
  r.add(std::make_unique<Fixed>("q1", Role::QuadCap | Role::MixedCap, true, 1));
  r.add(std::make_unique<Fixed>("t", Role::TriCap, true, 1));
  r.add(std::make_unique<Fixed>("free", Role::None, true, 1));
  r.add(std::make_unique<Fixed>("q2", Role::QuadCap, true, 1));
  std::vector<std::string> quad;
  for (const auto* s : r.surface_schemes(Role::QuadCap)) quad.emplace_back(s->name());
  EXPECT_EQ(quad, (std::vector<std::string>{"q1", "q2"}));
  EXPECT_EQ(r.surface_schemes(Role::MixedCap).size(), 1u);
  EXPECT_TRUE(r.surface_schemes(Role::SweepSide).empty());
  EXPECT_EQ(r.surface_schemes().size(), 4u);
}

TEST(BestSurfaceScheme, TheBestScoreWinsTiesKeepRegistrationOrder) {
  Registry r;
  r.add(std::make_unique<Fixed>("low", Role::QuadCap, true, 0.6));
  r.add(std::make_unique<Fixed>("no", Role::QuadCap, false, 0.0));
  r.add(std::make_unique<Fixed>("high", Role::QuadCap, true, 0.9));
  r.add(std::make_unique<Fixed>("high_too", Role::QuadCap, true, 0.9));
  r.add(std::make_unique<Fixed>("better_but_free", Role::None, true, 1.0));
  const RoleChoice c =
      best_surface_scheme(r, Role::QuadCap, SurfaceView{empty_model(), 1, nullptr});
  ASSERT_NE(c.scheme, nullptr);
  EXPECT_EQ(c.scheme->name(), "high");
  EXPECT_DOUBLE_EQ(c.applicability.score, 0.9);
  EXPECT_EQ(c.reasons, "no: no does not");
}

TEST(BestSurfaceScheme, NoneAppliesGivesEveryReasonOrSaysNoneServes) {
  Registry r;
  r.add(std::make_unique<Fixed>("a", Role::TriCap, false, 0));
  r.add(std::make_unique<Fixed>("b", Role::TriCap, false, 0));
  const RoleChoice c = best_surface_scheme(r, Role::TriCap, SurfaceView{empty_model(), 1, nullptr});
  EXPECT_EQ(c.scheme, nullptr);
  EXPECT_EQ(c.reasons, "a: a does not; b: b does not");
  const RoleChoice none =
      best_surface_scheme(r, Role::SweepSide, SurfaceView{empty_model(), 1, nullptr});
  EXPECT_EQ(none.scheme, nullptr);
  EXPECT_EQ(none.reasons, "no registered surface scheme serves sweep side");
}

}  // namespace
}  // namespace cooperage::scheme
