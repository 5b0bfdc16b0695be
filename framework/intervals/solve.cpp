#include "framework/intervals/solve.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/intervals/deviation.h"
#include "framework/intervals/ilp.h"

namespace cooperage::intervals {
namespace {

/// A constraint in canonical form over curve ids (see detail::Row).
struct Canonical {
  Constraint::Kind kind = Constraint::Kind::Linear;
  std::vector<std::pair<int, int>> terms;  ///< (curve id, coefficient), sorted by id
  Sense sense = Sense::Equal;
  int rhs = 0;
  std::string label;
  bool preferred = false;

  auto key() const { return std::tie(kind, terms, sense, rhs, label, preferred); }
};

Sense flipped(Sense s) {
  if (s == Sense::LessEqual) return Sense::GreaterEqual;
  if (s == Sense::GreaterEqual) return Sense::LessEqual;
  return s;
}

Canonical canonical(const Constraint& c) {
  std::map<int, int> merged;
  for (const LinearTerm& t : c.terms) merged[t.curve_id] += t.coeff;
  Canonical out;
  out.kind = c.kind;
  out.sense = c.sense;
  out.rhs = c.rhs;
  out.label = c.label;
  out.preferred = c.preferred;
  for (auto [id, coeff] : merged)
    if (coeff != 0) out.terms.emplace_back(id, coeff);
  if (!out.terms.empty() && out.terms.front().second < 0) {
    for (auto& term : out.terms) term.second = -term.second;
    out.rhs = -out.rhs;
    out.sense = flipped(out.sense);
  }
  return out;
}

/// True when a constraint without variables holds: 0 <sense> rhs.
bool constant_holds(const Canonical& c) {
  if (c.kind == Constraint::Kind::Even) return true;
  switch (c.sense) {
    case Sense::LessEqual: return 0 <= c.rhs;
    case Sense::Equal: return 0 == c.rhs;
    case Sense::GreaterEqual: return 0 >= c.rhs;
  }
  return false;
}

/// Union-find over curve indices.
struct Components {
  std::vector<int> parent;
  explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // root = smallest index
  }
};

/// The best count of a curve no constraint names: floor or ceil of its
/// target under the cost, clamped to its bounds (h is convex).
int lone_count(const Curve& curve) {
  if (curve.hard()) return *curve.fixed;
  const double target = curve.target();
  long lo = curve.min, hi = curve.max ? *curve.max : std::max<long>(lo, std::lround(target) + 1);
  const long below = std::clamp<long>(static_cast<long>(std::floor(target)), lo, hi);
  const long above = std::clamp<long>(static_cast<long>(std::ceil(target)), lo, hi);
  return static_cast<int>(deviation_cost(above, target) < deviation_cost(below, target) ? above
                                                                                        : below);
}

detail::Cost cost_of(const Curve& curve, const SolveOptions& options) {
  return {curve.target(), curve.firmness == Firmness::Soft ? options.soft_weight : 1.0};
}

/// One connected component: its curves (ascending) and canonical constraints (sorted).
struct Component {
  std::vector<const Curve*> curves;
  std::vector<Canonical> constraints;
};

/// Something that can make a component infeasible: a constraint or a bound.
struct Item {
  enum class Kind { Constraint, Fixed, Min, Max } kind;
  int index;  ///< constraint index, or column of the curve
  std::string text;
};

std::vector<Item> items_of(const Component& comp) {
  std::vector<Item> items;
  for (size_t k = 0; k < comp.constraints.size(); ++k)
    items.push_back({Item::Kind::Constraint, static_cast<int>(k), comp.constraints[k].label});
  for (size_t j = 0; j < comp.curves.size(); ++j) {
    const Curve& c = *comp.curves[j];
    const std::string name = "curve " + std::to_string(c.id);
    const int col = static_cast<int>(j);
    if (c.hard())
      items.push_back(
          {Item::Kind::Fixed, col, name + " fixed at " + std::to_string(*c.fixed) + " (hard)"});
    if (c.min > 1)
      items.push_back(
          {Item::Kind::Min, col, name + " at least " + std::to_string(c.min) + " (minimum)"});
    if (c.max)
      items.push_back(
          {Item::Kind::Max, col, name + " at most " + std::to_string(*c.max) + " (maximum)"});
  }
  return items;
}

/// True for "x_a = x_b": the curves can share one column.
bool is_plain_equality(const Canonical& c) {
  return c.kind == Constraint::Kind::Linear && c.sense == Sense::Equal && c.rhs == 0 &&
         c.terms.size() == 2 && c.terms[0].second == 1 && c.terms[1].second == -1;
}

/// The model of a component with only the active items switched on, curves
/// forced equal by active plain equalities (map faces) merged into one column
/// that carries all their costs (none when `with_costs` is false: a
/// feasibility check). `class_of[j]` is the column of curve j. Returns false
/// when the bounds or constraints are contradictory before any solve.
bool build_model(const Component& comp, const std::vector<Item>& items,
                 const std::vector<bool>& active, bool with_costs, const SolveOptions& options,
                 std::vector<int>& class_of, std::vector<detail::Column>& columns,
                 std::vector<detail::Row>& rows) {
  std::map<int, int> index_of;
  for (size_t j = 0; j < comp.curves.size(); ++j)
    index_of[comp.curves[j]->id] = static_cast<int>(j);
  Components same(comp.curves.size());
  for (size_t i = 0; i < items.size(); ++i) {
    if (!active[i] || items[i].kind != Item::Kind::Constraint) continue;
    const Canonical& c = comp.constraints[items[i].index];
    if (is_plain_equality(c)) same.join(index_of[c.terms[0].first], index_of[c.terms[1].first]);
  }

  class_of.assign(comp.curves.size(), -1);
  columns.clear();
  rows.clear();
  for (size_t j = 0; j < comp.curves.size(); ++j) {  // roots come first: smallest index
    const int root = same.find(static_cast<int>(j));
    if (class_of[root] < 0) {
      class_of[root] = static_cast<int>(columns.size());
      columns.emplace_back();
    }
    class_of[j] = class_of[root];
    const Curve& curve = *comp.curves[j];
    if (with_costs && !curve.hard()) columns[class_of[j]].costs.push_back(cost_of(curve, options));
  }
  for (size_t i = 0; i < items.size(); ++i) {
    if (!active[i]) continue;
    const Item& item = items[i];
    if (item.kind == Item::Kind::Constraint) {
      const Canonical& c = comp.constraints[item.index];
      if (is_plain_equality(c)) continue;
      std::map<int, int> merged;
      for (auto [id, coeff] : c.terms) merged[class_of[index_of[id]]] += coeff;
      detail::Row row{c.kind, {}, c.sense, c.rhs};
      for (auto [col, coeff] : merged)
        if (coeff != 0) row.terms.emplace_back(col, coeff);
      if (row.terms.empty()) {
        Canonical constant = c;
        constant.terms.clear();
        if (!constant_holds(constant)) return false;
        continue;
      }
      rows.push_back(std::move(row));
      continue;
    }
    const Curve& curve = *comp.curves[item.index];
    detail::Column& col = columns[class_of[item.index]];
    auto cap = [&col](int hi) { col.hi = col.hi ? std::min(*col.hi, hi) : hi; };
    if (item.kind == Item::Kind::Min) col.lo = std::max(col.lo, curve.min);
    if (item.kind == Item::Kind::Max) cap(*curve.max);
    if (item.kind == Item::Kind::Fixed) {
      col.lo = std::max(col.lo, *curve.fixed);
      cap(*curve.fixed);
    }
  }
  // A finite box so branch and bound always ends: twice the sum of every
  // curve's largest wish plus the constraint constants (no sensible
  // assignment comes near it).
  long box = 16;
  for (const Curve* curve : comp.curves)
    box += 2 * std::max<long>(
                   {std::lround(std::ceil(curve->target())), curve->min, curve->fixed.value_or(0)});
  for (const Canonical& c : comp.constraints) box += 2 * std::abs(static_cast<long>(c.rhs));
  const int cap_all = static_cast<int>(std::min<long>(box, 1L << 30));
  for (detail::Column& col : columns) {
    if (!col.hi) col.hi = std::max(cap_all, col.lo);
    if (*col.hi < col.lo) return false;
  }
  // Divisibility (integer infeasibility CBC does not always prove): with the
  // fixed columns moved to the right-hand side, the gcd of the remaining
  // coefficients (and 2 for a parity row) must divide it.
  for (const detail::Row& row : rows) {
    if (row.kind == Constraint::Kind::Linear && row.sense != Sense::Equal) continue;
    long constant = 0, divisor = row.kind == Constraint::Kind::Even ? 2 : 0;
    for (auto [col, coeff] : row.terms) {
      if (*columns[col].hi == columns[col].lo)
        constant += static_cast<long>(coeff) * columns[col].lo;
      else
        divisor = std::gcd(divisor, static_cast<long>(std::abs(coeff)));
    }
    const long rest = (row.kind == Constraint::Kind::Even ? 0 : row.rhs) - constant;
    if (divisor == 0 ? rest != 0 : rest % divisor != 0) return false;
  }
  return true;
}

/// Deletion filter (Chinneck): drop each item whose removal keeps the
/// system infeasible; what stays is an irreducible infeasible subset.
std::vector<bool> deletion_filter(const Component& comp, const std::vector<Item>& items,
                                  const SolveOptions& options) {
  SolveOptions check = options;
  check.max_seconds = std::min(options.max_seconds, options.iis_check_seconds);
  std::vector<bool> active(items.size(), true);
  std::vector<int> class_of;
  std::vector<detail::Column> columns;
  std::vector<detail::Row> rows;
  for (size_t i = 0; i < items.size(); ++i) {
    active[i] = false;
    const bool still_infeasible =
        !build_model(comp, items, active, false, check, class_of, columns, rows) ||
        detail::solve_ilp(columns, rows, check).status == detail::IlpStatus::Infeasible;
    if (!still_infeasible) active[i] = true;  // needed (or not provably redundant)
  }
  return active;
}

[[noreturn]] void throw_infeasible(const Component& comp, const SolveOptions& options) {
  const std::vector<Item> items = items_of(comp);
  std::vector<bool> active(items.size(), true);
  const bool narrowed = static_cast<int>(items.size()) < options.iis_item_limit;
  if (narrowed) active = deletion_filter(comp, items, options);
  std::set<int> curve_ids;
  std::string list;
  for (size_t i = 0; i < items.size(); ++i) {
    if (!active[i]) continue;
    const Item& item = items[i];
    list += (list.empty() ? "" : "; ") + item.text;
    if (item.kind == Item::Kind::Constraint) {
      for (auto [id, coeff] : comp.constraints[item.index].terms) curve_ids.insert(id);
    } else {
      curve_ids.insert(comp.curves[item.index]->id);
    }
  }
  std::string curves;
  for (int id : curve_ids) curves += (curves.empty() ? "" : ", ") + std::to_string(id);
  throw IntervalConflict(
      "interval constraints cannot all hold: " + list + " (curves " + curves + ")",
      std::move(curve_ids));
}

/// A cheap feasible start, if there is one of this form: every free column
/// at the same count v (even counts near the median target first; this
/// satisfies map equalities and loop parity), fixed columns at their value.
std::optional<std::vector<int>> uniform_start(const std::vector<detail::Column>& columns,
                                              const std::vector<detail::Row>& rows) {
  std::vector<double> targets;
  for (const detail::Column& col : columns)
    for (const detail::Cost& cost : col.costs) targets.push_back(cost.target);
  if (targets.empty()) return std::nullopt;
  std::nth_element(targets.begin(), targets.begin() + targets.size() / 2, targets.end());
  const int median = static_cast<int>(std::max(1L, std::lround(targets[targets.size() / 2])));
  std::vector<int> candidates;
  for (int v = median + median % 2; v >= 2; v -= 2) candidates.push_back(v);
  for (int v = median + median % 2 + 2; v <= 4 * median + 8; v += 2) candidates.push_back(v);
  for (int v = 1; v <= 4 * median + 8; v += 2) candidates.push_back(v);
  std::vector<int> x(columns.size());
  for (int v : candidates) {
    for (size_t j = 0; j < columns.size(); ++j) {
      const detail::Column& col = columns[j];
      x[j] = std::max(col.lo, col.hi ? std::min(*col.hi, v) : v);
    }
    if (detail::satisfies(columns, rows, x)) return x;
  }
  return std::nullopt;
}

/// The caller's start (SolveOptions::start) as column values, if it names
/// every curve of the component and satisfies its rows.
std::optional<std::vector<int>> given_start(const Component& comp, const std::vector<int>& class_of,
                                            const std::vector<detail::Column>& columns,
                                            const std::vector<detail::Row>& rows,
                                            const SolveOptions& options) {
  if (!options.start) return std::nullopt;
  std::vector<int> x(columns.size(), 0);
  for (size_t j = 0; j < comp.curves.size(); ++j) {
    const auto it = options.start->find(comp.curves[j]->id);
    if (it == options.start->end()) return std::nullopt;
    if (x[class_of[j]] != 0 && x[class_of[j]] != it->second) return std::nullopt;  // unequal pair
    x[class_of[j]] = it->second;
  }
  for (size_t k = 0; k < columns.size(); ++k) {
    if (x[k] < columns[k].lo || (columns[k].hi && x[k] > *columns[k].hi)) return std::nullopt;
  }
  if (!detail::satisfies(columns, rows, x)) return std::nullopt;
  return x;
}

std::vector<int> solve_component(const Component& comp, const SolveOptions& options) {
  const std::vector<Item> items = items_of(comp);
  std::vector<int> class_of;
  std::vector<detail::Column> columns;
  std::vector<detail::Row> rows;
  if (!build_model(comp, items, std::vector<bool>(items.size(), true), true, options, class_of,
                   columns, rows))
    throw_infeasible(comp, options);
  std::optional<std::vector<int>> start = given_start(comp, class_of, columns, rows, options);
  if (!start) start = uniform_start(columns, rows);
  if (!start) {
    // No uniform start (minimum counts from curve_sizing.h, e.g. a circle's
    // 6 opposite a line's 1 on a mapped face): a feasibility solve (no
    // costs, quick for CBC) gives it one; without, CBC searched for minutes
    // on a 378-curve real-cad component.
    std::vector<int> class_free;
    std::vector<detail::Column> plain;
    std::vector<detail::Row> plain_rows;
    if (build_model(comp, items, std::vector<bool>(items.size(), true), false, options, class_free,
                    plain, plain_rows)) {
      // Where it finds a start at all it does so at CBC's root (at most
      // 15 ms on the real-cad set). On gmsh_Zylkopf's 388-curve component
      // it found none in 10 s (112,000 nodes; 0.9 GB within the first
      // second; CBC's -maxNodes is not honoured in this search without
      // costs), and the full solve then took 0.6 s without a start.
      SolveOptions quick = options;
      quick.max_seconds = std::min(options.max_seconds, 0.25);
      const detail::IlpResult feasible = detail::solve_ilp(plain, plain_rows, quick);
      if ((feasible.status == detail::IlpStatus::Optimal ||
           feasible.status == detail::IlpStatus::Feasible) &&
          detail::satisfies(columns, rows, feasible.x)) {
        start = feasible.x;
      }
    }
  }
  const detail::IlpResult result =
      detail::solve_ilp(columns, rows, options, start ? &*start : nullptr);
  switch (result.status) {
    case detail::IlpStatus::Optimal: break;
    case detail::IlpStatus::Feasible:
      log::warning(
          "interval assignment: CBC stopped before proving optimality for the "
          "component of curve " +
          std::to_string(comp.curves.front()->id) + "; using the best solution found");
      break;
    case detail::IlpStatus::Infeasible: throw_infeasible(comp, options);
    case detail::IlpStatus::NoSolution:
      throw MeshingError(ErrorCode::Infeasible, EntityRef::curve(comp.curves.front()->id),
                         "interval assignment found no solution within " +
                             std::to_string(options.max_seconds) + " s for the " +
                             std::to_string(comp.curves.size()) + " curves linked to it");
  }
  std::vector<int> x(comp.curves.size());
  for (size_t j = 0; j < x.size(); ++j) x[j] = result.x[class_of[j]];
  return x;
}

std::string memo_key(const Component& comp);

/// Whether a preference holds for the counts (curve id -> count).
bool holds(const Canonical& c, const std::map<int, int>& counts) {
  long sum = 0;
  for (auto [id, coeff] : c.terms) sum += static_cast<long>(coeff) * counts.at(id);
  if (c.sense == Sense::Equal) return sum == c.rhs;
  return c.sense == Sense::LessEqual ? sum <= c.rhs : sum >= c.rhs;
}

/// solve_component through the memo, if any.
std::vector<int> solve_memo(Component& comp, const SolveOptions& options) {
  std::sort(comp.constraints.begin(), comp.constraints.end(),
            [](const Canonical& a, const Canonical& b) { return a.key() < b.key(); });
  if (!options.memo) return solve_component(comp, options);
  const std::string key = memo_key(comp);
  const auto known = options.memo->counts.find(key);
  std::vector<int> x =
      known != options.memo->counts.end() ? known->second : solve_component(comp, options);
  options.memo->counts.emplace(key, x);
  return x;
}

/// Everything solve_component's answer depends on, as text (goals exact,
/// in hexadecimal floating point).
std::string memo_key(const Component& comp) {
  std::ostringstream key;
  key << std::hexfloat;
  for (const Curve* c : comp.curves) {
    key << 'c' << c->id << ' ' << c->goal << ' ' << static_cast<int>(c->firmness) << ' '
        << (c->fixed ? *c->fixed : -1) << ' ' << c->min << ' ' << (c->max ? *c->max : -1) << ';';
  }
  for (const Canonical& k : comp.constraints) {
    key << 'k' << static_cast<int>(k.kind) << ' ' << static_cast<int>(k.sense) << ' ' << k.rhs;
    for (auto [id, coeff] : k.terms) key << ' ' << id << '*' << coeff;
    key << ' ' << k.label << (k.preferred ? " preferred" : "") << ';';
  }
  return key.str();
}

}  // namespace

void preload_solver() noexcept {
  try {
    detail::load_solver();
  } catch (...) {  // the first solve says why
  }
}

IntervalSolution solve(const IntervalProblem& problem, const SolveOptions& options) {
  const auto& curves = problem.curves();
  std::map<int, int> index_of;
  std::vector<const Curve*> by_index;
  for (const auto& [id, curve] : curves) {
    index_of[id] = static_cast<int>(by_index.size());
    by_index.push_back(&curve);
  }

  // Validate, canonicalise, and link curves named by the same constraint
  // (the needs; preferences come after, where the needs' answer breaks them).
  Components links(by_index.size());
  std::vector<Canonical> constraints, preferences;
  for (const Constraint& c : problem.constraints()) {
    for (const LinearTerm& t : c.terms)
      if (!problem.has_curve(t.curve_id))
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::curve(t.curve_id),
                           "interval constraint \"" + c.label + "\" names an unknown curve");
    Canonical canon = canonical(c);
    if (canon.terms.empty()) {
      // Its terms cancelled: no curve is to blame, so the conflict names none
      // (the selector then may relax any automatic choice).
      if (!constant_holds(canon) && !canon.preferred)
        throw IntervalConflict("interval constraints cannot all hold: " + c.label, {});
      continue;
    }
    if (canon.preferred) {
      preferences.push_back(std::move(canon));
      continue;
    }
    for (auto [id, coeff] : canon.terms)
      links.join(index_of[canon.terms.front().first], index_of[id]);
    constraints.push_back(std::move(canon));
  }

  // Components keyed by their root, which is their smallest curve index
  // (= smallest id): std::map iterates them in ascending smallest curve id.
  std::map<int, Component> components;
  for (size_t i = 0; i < by_index.size(); ++i)
    components[links.find(static_cast<int>(i))].curves.push_back(by_index[i]);
  for (Canonical& c : constraints)
    components[links.find(index_of[c.terms.front().first])].constraints.push_back(std::move(c));

  IntervalSolution solution;
  solution.sizes = problem.size_functions();
  for (auto& [root, comp] : components) {
    if (comp.constraints.empty()) {
      for (const Curve* curve : comp.curves) solution.intervals[curve->id] = lone_count(*curve);
      continue;
    }
    const std::vector<int> x = solve_memo(comp, options);
    for (size_t j = 0; j < comp.curves.size(); ++j) solution.intervals[comp.curves[j]->id] = x[j];
  }

  // Preferences the needs' answer breaks: the components they touch are
  // solved again as one, with the needs and every preference among their
  // curves; where that cannot hold, the needs' answer stays. Preferences
  // that hold already change nothing (a row CBC does not need still moves
  // its answer within the optimality gap).
  Components groups = links;
  std::vector<const Canonical*> broken;
  for (const Canonical& c : preferences) {
    if (holds(c, solution.intervals)) continue;
    broken.push_back(&c);
    for (auto [id, coeff] : c.terms) groups.join(index_of[c.terms.front().first], index_of[id]);
  }
  if (!broken.empty()) {
    std::map<int, Component> regrouped;
    std::set<int> touched;
    for (const Canonical* c : broken) touched.insert(groups.find(index_of[c->terms.front().first]));
    for (size_t i = 0; i < by_index.size(); ++i) {
      const int g = groups.find(static_cast<int>(i));
      if (touched.count(g)) regrouped[g].curves.push_back(by_index[i]);
    }
    for (auto& [root, comp] : components) {
      for (const Canonical& c : comp.constraints) {
        const int g = groups.find(index_of[c.terms.front().first]);
        if (touched.count(g)) regrouped[g].constraints.push_back(c);
      }
    }
    for (const Canonical& c : preferences) {
      const int g = groups.find(index_of[c.terms.front().first]);
      bool inside = touched.count(g) > 0;
      for (auto [id, coeff] : c.terms) inside = inside && groups.find(index_of[id]) == g;
      if (inside) regrouped[g].constraints.push_back(c);
    }
    for (auto& [root, comp] : regrouped) {
      try {
        const std::vector<int> x = solve_memo(comp, options);
        for (size_t j = 0; j < comp.curves.size(); ++j)
          solution.intervals[comp.curves[j]->id] = x[j];
      } catch (const IntervalConflict&) {
        log::info("interval assignment: the preferences on the curves of curve " +
                  std::to_string(comp.curves.front()->id) +
                  " cannot hold with the needs; left out");
      }
    }
  }

  for (const auto& [id, count] : solution.intervals) {
    const Curve& curve = curves.at(id);
    solution.deviation[id] = relative_deviation(count, curve.target());
    if (!curve.hard()) {
      const double weight = curve.firmness == Firmness::Soft ? options.soft_weight : 1.0;
      solution.objective += weight * deviation_cost(count, curve.target());
    }
  }
  return solution;
}

}  // namespace cooperage::intervals
