// The interval constraints of a barrel tree (Blacker 1996, sec. 3-4; DESIGN
// "cooper: side faces' sweep-direction intervals consistent per barrel"),
// as plain rows. Every level class gets a layer potential from the chains
// (a spanning tree; each further chain is an equality: parallel links have
// equal counts, a chain past several levels equals the sum of its pieces);
// the classes of one barrel end are equal; every barrel has at least one
// layer (so a blind hole's floor stays above the bottom: the outer wall
// runs past the floor's level without a vertex there). When a polygon
// mesher meshes imprinted pieces all-quad, every cap loop is even (sec.
// 5.3: even parity); so is every loop of a cap paved beforehand with
// several loops (pave joins odd loops by paths it does not always find).
// Plain data: testable without CAD.
#pragma once

#include "framework/intervals/interval_problem.h"
#include "schemes/cooper/barrel_tree.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

struct IntervalRow {
  std::map<int, int> terms;  ///< curve id -> coefficient (no zeros)
  intervals::Sense sense = intervals::Sense::Equal;
  int rhs = 0;
  bool even = false;  ///< sum(terms) even instead (coefficients 1)
  std::string label;
  bool preferred = false;  ///< kept where the rest allows (intervals::Constraint::preferred)
};

/// Layer potentials: per level class, curve coefficients of lambda(class)
/// - lambda(root of its component); `extra` receives the chains left out
/// of the spanning tree (indices into lattice.chains).
std::vector<std::map<int, int>> layer_potentials(const SideLattice& lattice,
                                                 const SweepOrder& order,
                                                 std::vector<size_t>* extra = nullptr);

/// The rows; every loop of `even_caps` is even; `tag` starts every label
/// ("volume 3 (cooper)"). With a `layer_size` (the element size along the
/// sweep; 0: none), on a straight sweep, a ring of vertices between two
/// cap levels more than a quarter of it from one of them is preferably a
/// layer away from it.
std::vector<IntervalRow> barrel_constraints(const VolumeFacts& facts, const SideLattice& lattice,
                                            const SweepOrder& order, const BarrelTree& tree,
                                            const std::set<int>& even_caps, const std::string& tag,
                                            double layer_size = 0);

/// Adds the rows to an interval problem.
void add_rows(const std::vector<IntervalRow>& rows, intervals::IntervalProblem& problem);

}  // namespace cooperage::cooper
