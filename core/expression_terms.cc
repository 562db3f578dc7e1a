#include "core/expression_terms.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>

#include "core/check.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

constexpr std::size_t kMaxTerms = 1000;

using Monomial = std::vector<std::string>;      // sorted factors; empty for the constant
using Polynomial = std::map<Monomial, double>;  // monomial -> coefficient, no zeros

std::string MonomialText(const Monomial& m) {
  if (m.empty()) return "1";
  std::string text = m.front();
  for (std::size_t i = 1; i < m.size(); ++i) text += "*" + m[i];
  return text;
}

std::string PolynomialText(const Polynomial& p) {
  if (p.empty()) return "0";
  std::string text;
  for (const auto& [m, c] : p) {
    const bool negative = std::signbit(c);
    if (text.empty()) {
      if (negative) text = "-";
    } else {
      text += negative ? " - " : " + ";
    }
    const double magnitude = std::abs(c);
    if (m.empty()) {
      text += FormatNumber(magnitude);
    } else {
      if (magnitude != 1.0) text += FormatNumber(magnitude) + "*";
      text += MonomialText(m);
    }
  }
  return text;
}

Polynomial Atom(std::string factor) { return {{Monomial{std::move(factor)}, 1.0}}; }

Polynomial Constant(double c) {
  if (c == 0.0) return {};
  return {{Monomial{}, c}};
}

bool IsConstant(const Polynomial& p, double* value) {
  if (p.empty()) {
    *value = 0.0;
    return true;
  }
  if (p.size() == 1 && p.begin()->first.empty()) {
    *value = p.begin()->second;
    return true;
  }
  return false;
}

void Accumulate(Polynomial& sum, const Monomial& m, double c) {
  const auto [it, inserted] = sum.emplace(m, c);
  if (!inserted) it->second += c;
  if (it->second == 0.0) sum.erase(it);
}

Polynomial Add(Polynomial p, const Polynomial& q, double sign) {
  for (const auto& [m, c] : q) Accumulate(p, m, sign * c);
  return p;
}

Polynomial Multiply(const Polynomial& p, const Polynomial& q) {
  if (p.size() * q.size() > kMaxTerms)
    return Atom("(" + PolynomialText(p) + ")*(" + PolynomialText(q) + ")");
  Polynomial product;
  for (const auto& [mp, cp] : p) {
    for (const auto& [mq, cq] : q) {
      Monomial m;
      m.reserve(mp.size() + mq.size());
      std::merge(mp.begin(), mp.end(), mq.begin(), mq.end(), std::back_inserter(m));
      Accumulate(product, m, cp * cq);
    }
  }
  return product;
}

Polynomial DivideCoefficients(Polynomial p, double c) {
  for (auto it = p.begin(); it != p.end();) {
    it->second /= c;
    it = it->second == 0.0 ? p.erase(it) : std::next(it);
  }
  return p;
}

// The factor 1/f, parenthesised where "1/" would bind to less than f.
std::string Reciprocal(const std::string& factor) {
  const bool simple = factor.front() != '(' && factor.rfind("1/", 0) != 0;
  return simple ? "1/" + factor : "1/(" + factor + ")";
}

Polynomial Divide(const Polynomial& p, const Polynomial& q) {
  double c = 0.0;
  if (IsConstant(q, &c)) {
    return std::abs(c) < kProtectedDivisionEpsilon ? p : DivideCoefficients(p, c);
  }
  if (q.size() == 1) {
    const auto& [m, cq] = *q.begin();
    Monomial reciprocals;
    for (const std::string& factor : m) reciprocals.push_back(Reciprocal(factor));
    std::sort(reciprocals.begin(), reciprocals.end());
    return Multiply(DivideCoefficients(p, cq), {{reciprocals, 1.0}});
  }
  return Multiply(p, Atom("1/(" + PolynomialText(q) + ")"));
}

Polynomial Function(OpCode op, const Polynomial& p) {
  double c = 0.0;
  if (IsConstant(p, &c) && std::isfinite(ApplyOperator(op, c))) {
    return Constant(ApplyOperator(op, c));
  }
  if (op == OpCode::kAbs && p.size() == 1) {
    const auto& [m, cp] = *p.begin();
    return {{Monomial{"abs(" + MonomialText(m) + ")"}, std::abs(cp)}};
  }
  return Atom(std::string(FunctionName(op)) + "(" + PolynomialText(p) + ")");
}

}  // namespace

std::vector<std::pair<std::string, double>> ExpandTerms(std::span<const Instruction> program,
                                                        std::span<const std::string> variables) {
  std::vector<Polynomial> stack;
  for (const Instruction& in : program) {
    switch (in.op) {
      case OpCode::kConstant:
        stack.push_back(Constant(in.value));
        break;
      case OpCode::kVariable:
        stack.push_back(Atom(variables[static_cast<std::size_t>(in.index)]));
        break;
      case OpCode::kNegate:
        for (auto& term : stack.back()) term.second = -term.second;
        break;
      case OpCode::kAdd:
      case OpCode::kSubtract:
      case OpCode::kMultiply:
      case OpCode::kDivide: {
        Polynomial right = std::move(stack.back());
        stack.pop_back();
        Polynomial& left = stack.back();
        if (in.op == OpCode::kAdd) left = Add(std::move(left), right, 1.0);
        if (in.op == OpCode::kSubtract) left = Add(std::move(left), right, -1.0);
        if (in.op == OpCode::kMultiply) left = Multiply(left, right);
        if (in.op == OpCode::kDivide) left = Divide(left, right);
        break;
      }
      default:
        stack.back() = Function(in.op, stack.back());
        break;
    }
  }
  USVID_CHECK(stack.size() == 1, "a parsed program leaves one value");
  std::map<std::string, double> merged;
  for (const auto& [m, c] : stack.back()) merged[MonomialText(m)] += c;
  std::vector<std::pair<std::string, double>> terms;
  for (const auto& [text, c] : merged) {
    if (c != 0.0) terms.emplace_back(text, c);
  }
  return terms;
}

}  // namespace usvid
