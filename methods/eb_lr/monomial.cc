#include "methods/eb_lr/monomial.h"

#include <cmath>
#include <sstream>

#include "core/error.h"

namespace usvid::eb_lr {
namespace {

std::string Trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

[[noreturn]] void Fail(const std::string& option, const std::string& item, const std::string& why) {
  throw InputError(option + ": term '" + item + "': " + why +
                   " (terms are products of 1, U, r, abs(r) with optional ^n, e.g. U^2*r)");
}

}  // namespace

double Monomial::Evaluate(double speed, double rate) const {
  double v = 1.0;
  for (int i = 0; i < speed_power; ++i) v *= speed;
  for (int j = 0; j < rate_power; ++j) v *= (abs_rate && j == 0) ? std::abs(rate) : rate;
  return v;
}

std::string Monomial::Text(const std::string& speed, const std::string& rate) const {
  std::string s;
  auto add = [&s](const std::string& f) { s += (s.empty() ? "" : "*") + f; };
  for (int i = 0; i < speed_power; ++i) add(speed);
  for (int j = 0; j < rate_power; ++j) add(abs_rate && j == 0 ? "abs(" + rate + ")" : rate);
  return s.empty() ? "1" : s;
}

double Combination(const std::vector<Monomial>& basis, const Eigen::VectorXd& c, double speed,
                   double rate) {
  double v = 0.0;
  for (size_t j = 0; j < basis.size(); ++j) v += c(j) * basis[j].Evaluate(speed, rate);
  return v;
}

std::vector<Monomial> ParseBasis(const std::string& list, const std::string& option) {
  std::vector<Monomial> basis;
  std::stringstream in(list);
  for (std::string raw; std::getline(in, raw, ',');) {
    const std::string item = Trim(raw);
    if (item.empty()) Fail(option, raw, "empty term");
    Monomial m;
    int abs_count = 0;
    std::stringstream factors(item);
    for (std::string f; std::getline(factors, f, '*');) {
      f = Trim(f);
      int power = 1;
      if (const auto caret = f.find('^'); caret != std::string::npos) {
        const std::string p = Trim(f.substr(caret + 1));
        if (p.empty() || p.size() > 2 || p.find_first_not_of("0123456789") != std::string::npos)
          Fail(option, item, "power '" + p + "' is not an integer from 0 to 99");
        power = std::stoi(p);
        f = Trim(f.substr(0, caret));
      }
      if (f == "1") continue;
      if (f == "U") {
        m.speed_power += power;
      } else if (f == "r") {
        m.rate_power += power;
      } else if (f == "abs(r)" || f == "|r|") {
        m.rate_power += power;
        abs_count += power;
      } else {
        Fail(option, item, "unknown factor '" + f + "'");
      }
    }
    m.abs_rate = abs_count % 2 == 1;
    for (const Monomial& b : basis)
      if (b == m) Fail(option, item, "listed twice");
    basis.push_back(m);
  }
  if (basis.empty()) throw InputError(option + ": the basis is empty");
  return basis;
}

std::string BasisText(const std::vector<Monomial>& basis) {
  std::string s;
  for (const Monomial& m : basis) {
    std::string t;
    auto add = [&t](const std::string& f, int p) {
      if (p == 0) return;
      t += (t.empty() ? "" : "*") + f + (p > 1 ? "^" + std::to_string(p) : "");
    };
    add("U", m.speed_power);
    if (m.abs_rate) add("abs(r)", 1);
    add("r", m.rate_power - (m.abs_rate ? 1 : 0));
    s += (s.empty() ? "" : ",") + (t.empty() ? "1" : t);
  }
  return s;
}

}  // namespace usvid::eb_lr
