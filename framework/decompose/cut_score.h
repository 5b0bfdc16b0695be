// How good a candidate cut is (issue 17): by the number of pieces, the
// pieces' a-priori scheme scores and the thinnest piece relative to the
// element size. Pure arithmetic on a summary, so it is tested alone.
#pragma once

namespace cooperage::decompose {

/// What one cut gives.
struct CutOutcome {
  int pieces = 0;                  ///< solids after the cut (>= 2)
  int failing = 0;                 ///< pieces no volume scheme applies to
  double min_score = 0.0;          ///< lowest a-priori score of the applicable pieces
  double mean_score = 0.0;         ///< mean a-priori score of the applicable pieces
  double thinnest = 0.0;           ///< thinnest piece across the cut / element size (>= 1)
  double meshable_fraction = 0.0;  ///< volume of the applicable pieces / volume cut
};

/// Score of a cut all of whose pieces a scheme applies to: one piece more
/// always costs more than any difference in scheme scores or thickness;
/// then the weakest piece's score, the mean score, and thickness up to four
/// element layers (thicker earns nothing more).
double complete_score(const CutOutcome& outcome);

/// Score of a cut that leaves pieces to cut again: the share of the volume
/// already meshable first, fewer failing pieces next, then thickness.
double partial_score(const CutOutcome& outcome);

/// a is better than b, comparing scores with a relative tolerance so that
/// rounding (a rotated part) never reorders equal candidates.
bool better(double a, double b);

}  // namespace cooperage::decompose
