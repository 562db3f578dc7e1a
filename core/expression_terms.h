// Term-level structure of an equation, for structure-recovery metrics (term precision/recall and
// coefficient error against the true model): the expression expanded into a sum of products.
//
// Normal form of a term (the coefficient is returned apart):
//   - factors sorted as strings and joined by '*': "r*v", "abs(u)*u"; powers are repeated
//     products ("u*u*u"); the constant term is "1";
//   - a variable is its name; a function of anything but a constant is one factor holding its
//     argument in normal form, "tanh(u + v)", with abs(c*m) = |c|*abs(m) pulled apart;
//   - x / c distributes over x for a number c (protected: |c| < 1e-12 leaves x); x / (c*m) for
//     one term c*m gives (x/c) times a factor "1/f" for each factor f of m, so that a/(b*c) and
//     a/b/c both give "1/b*1/c*a"; any other divisor y stays one factor "1/(y)";
//   - like terms are merged and terms whose coefficient is exactly 0 dropped (so u - u has no
//     terms); a product that would expand into more than 1000 terms stays one factor.
// Every term reads back with Expression::Parse.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/expression.h"

namespace usvid {

// (term, coefficient) pairs sorted by term, for a postfix program over `variables`.
std::vector<std::pair<std::string, double>> ExpandTerms(std::span<const Instruction> program,
                                                        std::span<const std::string> variables);

}  // namespace usvid
