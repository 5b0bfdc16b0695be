// The global interval-assignment problem as plain data: one integer variable
// per curve (its number of mesh intervals) with a goal, and the linear
// constraints the schemes need (ALGORITHMS.md sec. 2; Mitchell 1997, 2013).
// No geometry here: curves are integer ids, constraints carry a sentence for
// a person. solve() (solve.h) turns it into integer programs for CBC.
#pragma once

#include "framework/mesh/curve_spacing.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cooperage::intervals {

/// How strongly a curve holds on to its goal (Cubit's firmness).
enum class Firmness {
  Default,  ///< goal from the size; may move as the constraints need
  Soft,     ///< goal weighted more strongly than Default (SolveOptions::soft_weight)
  Hard,     ///< a constant: the user's fixed count, never changed
};

/// One curve: the variable x >= min (<= max), aiming at goal.
struct Curve {
  int id = 0;
  double goal = 1.0;  ///< intervals wanted (length / size), > 0
  Firmness firmness = Firmness::Default;
  std::optional<int> fixed;  ///< user's count: the value of a Hard curve, the goal otherwise
  int min = 1;               ///< lower bound, >= 1
  std::optional<int> max;    ///< upper bound, none = unbounded

  /// The value the objective aims at: `fixed` if given, else `goal`.
  double target() const { return fixed ? static_cast<double>(*fixed) : goal; }
  bool hard() const { return firmness == Firmness::Hard; }
};

/// coeff * x[curve_id].
struct LinearTerm {
  int curve_id = 0;
  int coeff = 1;
};

enum class Sense { LessEqual, Equal, GreaterEqual };

/// sum(terms) <sense> rhs, or (kind Even) sum(terms) == 2 m for an integer m.
struct Constraint {
  enum class Kind { Linear, Even };
  Kind kind = Kind::Linear;
  std::vector<LinearTerm> terms;
  Sense sense = Sense::Equal;  ///< Linear only
  int rhs = 0;                 ///< Linear only
  std::string label;           ///< "surface 7 (map): curves 1+3 = 2+4"
  /// A preference, not a need: solve() applies it only where the needs'
  /// answer breaks it, and leaves it out where it cannot hold with them (the
  /// order of a wall's corners, which the wall's geometry suggests and a
  /// sampled curve can misjudge).
  bool preferred = false;
};

/// Curves and constraints of one model. Constraints may name curves that are
/// added later; ids are checked by solve() (unknown id -> InvalidInput).
class IntervalProblem {
 public:
  /// Adds a curve.
  /// \param[in] curve_id  the curve's id (unique; re-adding identical data is a no-op)
  /// \param[in] goal      intervals wanted, > 0 (length / size)
  /// \param[in] firmness  Hard: the count is `fixed` (or round(goal) without it)
  /// \param[in] fixed     the user's count: constant if Hard, the goal otherwise
  /// \param[in] min,max   bounds on the count, 1 <= min <= max
  /// \throws MeshingError(InvalidInput) on goal <= 0, min < 1, max < min,
  ///         fixed outside [min, max], or a different curve with the same id.
  void add_curve(int curve_id, double goal, Firmness firmness = Firmness::Default,
                 std::optional<int> fixed = std::nullopt, int min = 1,
                 std::optional<int> max = std::nullopt);

  /// sum(lhs) == sum(rhs) (map: opposite sides; submap: per-direction sums).
  void add_equal(const std::vector<int>& lhs, const std::vector<int>& rhs, std::string label = {});
  /// sum(ids) even (pave: all-quad needs an even boundary), via sum = 2 m.
  void add_even(const std::vector<int>& ids, std::string label = {});
  /// sum(ids) >= k (pave: at least 4 intervals around a loop).
  void add_at_least(const std::vector<int>& ids, int k, std::string label = {});
  /// sum(coeff * x) <sense> rhs, e.g. "c2 + c3 >= c4 + c5 + 4".
  void add_linear(std::vector<LinearTerm> terms, Sense sense, int rhs, std::string label = {});

  /// As add_linear, kept only where the other constraints allow it
  /// (Constraint::preferred).
  void add_preference(std::vector<LinearTerm> terms, Sense sense, int rhs, std::string label = {});

  /// Where a curve's intervals should be smaller than its goal's mean (a
  /// small feature nearby, curve_sizing.h): its nodes follow these sizes.
  void set_size_function(int curve_id, mesh::SizeFunction sizes) {
    sizes_[curve_id] = std::move(sizes);
  }
  /// Back to uniform spacing (a sweep needs the curves along its sides spaced
  /// alike on both ends, cooper/side_lattice.h).
  void drop_size_function(int curve_id) { sizes_.erase(curve_id); }
  const std::map<int, mesh::SizeFunction>& size_functions() const { return sizes_; }

  const std::map<int, Curve>& curves() const { return curves_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }
  bool has_curve(int curve_id) const { return curves_.count(curve_id) != 0; }

 private:
  std::map<int, Curve> curves_;
  std::vector<Constraint> constraints_;
  std::map<int, mesh::SizeFunction> sizes_;
};

/// "1 + 3 = 2 + 4"-style text of a constraint, used when no label is given.
std::string describe(const Constraint& constraint);

}  // namespace cooperage::intervals
