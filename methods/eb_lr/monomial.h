// Monomials in speed U and rate r, the regressors of the Eriksen-Breivik model (eb_lr.h):
//   U^i r^j,   or with abs_rate   U^i |r| r^(j-1)   (j >= 1; |r| r is the odd form of r^2).
// Written in the equation syntax (docs/data.md#equation-syntax) with the caller's channel names
// ("U*U*r", "abs(r)*r", "1"); parsed from lists such as "U,U^2,U^3,r^2" or "1,U,abs(r)*r" whose
// factors are 1, U, r and abs(r) (or |r|), each with an optional integer power ^n (n >= 0).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace usvid::eb_lr {

struct Monomial {
  int speed_power = 0;
  int rate_power = 0;
  bool abs_rate = false;  // one factor r taken as |r|; needs rate_power >= 1

  double Evaluate(double speed, double rate) const;
  // "1" for the constant; factors joined by '*', speed first.
  std::string Text(const std::string& speed, const std::string& rate) const;
  bool operator==(const Monomial&) const = default;
};

// sum_j c(j) basis[j](speed, rate); c has one coefficient per term.
double Combination(const std::vector<Monomial>& basis, const Eigen::VectorXd& c, double speed,
                   double rate);

// Throws InputError naming `option` and the item: an empty list or item, an unknown factor, a
// bad power, a term listed twice.
std::vector<Monomial> ParseBasis(const std::string& list, const std::string& option);
// The list in ParseBasis's syntax (with U and r), e.g. "U,U^2,U^3,r^2".
std::string BasisText(const std::vector<Monomial>& basis);

}  // namespace usvid::eb_lr
