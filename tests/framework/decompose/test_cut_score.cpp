// cut_score.h: the order of candidate cuts.
#include "framework/decompose/cut_score.h"

#include <gtest/gtest.h>

namespace cooperage::decompose {
namespace {

CutOutcome outcome(int pieces, double min_score, double thinnest) {
  CutOutcome o;
  o.pieces = pieces;
  o.min_score = min_score;
  o.mean_score = min_score;
  o.thinnest = thinnest;
  o.meshable_fraction = 1.0;
  return o;
}

TEST(CutScore, OnePieceMoreCostsMoreThanAnyScoreOrThickness) {
  EXPECT_GT(complete_score(outcome(2, 0.0, 1.0)), complete_score(outcome(3, 1.0, 100.0)));
}

TEST(CutScore, BetterSchemesAndThickerPiecesWinAtEqualCount) {
  EXPECT_GT(complete_score(outcome(2, 0.9, 2.0)), complete_score(outcome(2, 0.5, 2.0)));
  EXPECT_GT(complete_score(outcome(2, 0.9, 3.0)), complete_score(outcome(2, 0.9, 1.0)));
}

TEST(CutScore, ThicknessBeyondFourLayersEarnsNothing) {
  EXPECT_DOUBLE_EQ(complete_score(outcome(2, 0.9, 4.0)), complete_score(outcome(2, 0.9, 40.0)));
}

TEST(CutScore, PartialCutsRankByTheShareAlreadyMeshable) {
  CutOutcome a = outcome(2, 0.9, 1.0), b = outcome(2, 0.9, 4.0);
  a.failing = b.failing = 1;
  a.meshable_fraction = 0.8;
  b.meshable_fraction = 0.3;
  EXPECT_GT(partial_score(a), partial_score(b));
}

TEST(CutScore, BetterIgnoresRoundingDifferences) {
  EXPECT_FALSE(better(1.0 + 1e-13, 1.0));
  EXPECT_FALSE(better(1.0, 1.0 + 1e-13));
  EXPECT_TRUE(better(1.0 + 1e-6, 1.0));
}

}  // namespace
}  // namespace cooperage::decompose
