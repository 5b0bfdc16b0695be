// The part's ids in what the decomposition says about pieces. A cut's pieces
// get a model of their own, numbered afresh by the kernel, so "surface 39" in
// a piece's refusal or "plane of surface 7" for a cut of a piece would point
// at an unrelated face of the part the user has (`cooperage plan`, `info`).
// Each entity of a piece lies on one of the part's (a face split by a cut is
// part of the face it was) or on a cut; it is named by that.
#pragma once

#include "framework/geometry/model.h"

#include <string>

namespace cooperage::decompose {

class PartIds {
 public:
  /// What an id in a text names.
  enum class Kind { Surface, Curve, Vertex, Volume };

  /// `part`: the model the user's ids come from; `volume`: the volume of it
  /// being cut (the pieces lie inside it).
  PartIds(const geom::Model& part, int volume);

  /// `text` about entities of `pieces` (a model of pieces of the volume)
  /// with their ids replaced by the part's: "surface N" (also "surfaces",
  /// "side(s)", "cap(s)"; lists "1, 2 and 3" too), "curve N", "vertex N"
  /// become the part's entity each lies on, or "the cut face", "a curve of
  /// the cut", "a vertex of the cut" where it lies on none; "volume N"
  /// becomes "the piece" for `piece` and "piece N" for the others. A face
  /// shared by two volumes of `pieces` is the cut between them.
  std::string translate(const std::string& text, const geom::Model& pieces, int piece = 0) const;

  /// The part's surface that piece surface `id` of `pieces` is (part of);
  /// 0 when it lies on none (a cut face).
  int surface(const geom::Model& pieces, int id) const;
  /// The part's curve that piece curve `id` lies on; 0 for none.
  int curve(const geom::Model& pieces, int id) const;
  /// The part's vertex at piece vertex `id`; 0 for none.
  int vertex(const geom::Model& pieces, int id) const;

 private:
  /// The part's name for entity `id` of `pieces`.
  std::string name(Kind kind, const geom::Model& pieces, int id, int piece) const;

  const geom::Model& part_;
  std::vector<int> surfaces_, curves_, vertices_;  ///< the volume's, ascending
  double tolerance_ = 0.0;
};

}  // namespace cooperage::decompose
