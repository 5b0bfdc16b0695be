#include "framework/intervals/interval_problem.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "framework/core/error.h"

namespace cooperage::intervals {
namespace {

[[noreturn]] void invalid(int curve_id, const std::string& message) {
  throw MeshingError(ErrorCode::InvalidInput, EntityRef::curve(curve_id), message);
}

bool same(const Curve& a, const Curve& b) {
  return a.goal == b.goal && a.firmness == b.firmness && a.fixed == b.fixed && a.min == b.min &&
         a.max == b.max;
}

std::vector<LinearTerm> terms_of(const std::vector<int>& ids, int coeff) {
  std::vector<LinearTerm> terms;
  terms.reserve(ids.size());
  for (int id : ids) terms.push_back({id, coeff});
  return terms;
}

const char* sense_text(Sense sense) {
  switch (sense) {
    case Sense::LessEqual: return "<=";
    case Sense::Equal: return "=";
    case Sense::GreaterEqual: return ">=";
  }
  return "?";
}

}  // namespace

void IntervalProblem::add_curve(int curve_id, double goal, Firmness firmness,
                                std::optional<int> fixed, int min, std::optional<int> max) {
  if (!std::isfinite(goal) || goal <= 0.0)
    invalid(curve_id, "interval goal must be positive, got " + std::to_string(goal));
  if (min < 1) invalid(curve_id, "minimum interval count must be >= 1, got " + std::to_string(min));
  if (max && *max < min)
    invalid(curve_id, "maximum interval count " + std::to_string(*max) + " is below the minimum " +
                          std::to_string(min));
  if (firmness == Firmness::Hard && !fixed) {
    // A hard curve without a count holds its rounded goal.
    long rounded = std::max(1L, std::lround(goal));
    rounded = std::max<long>(rounded, min);
    if (max) rounded = std::min<long>(rounded, *max);
    fixed = static_cast<int>(rounded);
  }
  if (fixed && *fixed < min)
    invalid(curve_id, "fixed interval count " + std::to_string(*fixed) + " is below the minimum " +
                          std::to_string(min));
  if (fixed && max && *fixed > *max)
    invalid(curve_id, "fixed interval count " + std::to_string(*fixed) + " is above the maximum " +
                          std::to_string(*max));
  Curve curve{curve_id, goal, firmness, fixed, min, max};
  auto [it, inserted] = curves_.emplace(curve_id, curve);
  if (!inserted && !same(it->second, curve))
    invalid(curve_id, "added twice with different interval settings");
}

void IntervalProblem::add_equal(const std::vector<int>& lhs, const std::vector<int>& rhs,
                                std::string label) {
  if (label.empty()) {
    auto join = [](const std::vector<int>& ids) {
      std::string text;
      for (int id : ids) text += (text.empty() ? "" : " + ") + std::to_string(id);
      return text.empty() ? std::string("0") : text;
    };
    label = "curves " + join(lhs) + " = " + join(rhs);
  }
  std::vector<LinearTerm> terms = terms_of(lhs, 1);
  for (const LinearTerm& t : terms_of(rhs, -1)) terms.push_back(t);
  add_linear(std::move(terms), Sense::Equal, 0, std::move(label));
}

void IntervalProblem::add_even(const std::vector<int>& ids, std::string label) {
  Constraint c;
  c.kind = Constraint::Kind::Even;
  c.terms = terms_of(ids, 1);
  c.label = label.empty() ? describe(c) : std::move(label);
  constraints_.push_back(std::move(c));
}

void IntervalProblem::add_at_least(const std::vector<int>& ids, int k, std::string label) {
  add_linear(terms_of(ids, 1), Sense::GreaterEqual, k, std::move(label));
}

void IntervalProblem::add_linear(std::vector<LinearTerm> terms, Sense sense, int rhs,
                                 std::string label) {
  Constraint c;
  c.kind = Constraint::Kind::Linear;
  c.terms = std::move(terms);
  c.sense = sense;
  c.rhs = rhs;
  c.label = label.empty() ? describe(c) : std::move(label);
  constraints_.push_back(std::move(c));
}

void IntervalProblem::add_preference(std::vector<LinearTerm> terms, Sense sense, int rhs,
                                     std::string label) {
  add_linear(std::move(terms), sense, rhs, std::move(label));
  constraints_.back().preferred = true;
}

std::string describe(const Constraint& constraint) {
  std::ostringstream out;
  out << "curves ";
  bool first = true;
  for (const LinearTerm& t : constraint.terms) {
    if (t.coeff == 0) continue;
    if (!first)
      out << (t.coeff < 0 ? " - " : " + ");
    else if (t.coeff < 0)
      out << "-";
    const int magnitude = std::abs(t.coeff);
    if (magnitude != 1) out << magnitude << "*";
    out << t.curve_id;
    first = false;
  }
  if (first) out << "(none)";
  if (constraint.kind == Constraint::Kind::Even) {
    out << " even";
  } else {
    out << " " << sense_text(constraint.sense) << " " << constraint.rhs;
  }
  return out.str();
}

}  // namespace cooperage::intervals
