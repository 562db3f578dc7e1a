#include "metrics/structure.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/expression.h"

namespace usvid {
namespace {

std::vector<std::string> FoundTerms(const std::string& equation) {
  std::vector<std::string> names;
  for (const auto& [term, coefficient] : Expression::Parse(equation, "equation").Terms())
    if (term != "1" && coefficient != 0.0) names.push_back(term);
  return names;
}

}  // namespace

StructureScore ScoreStructure(const std::string& equation, const std::vector<std::string>& truth) {
  const std::vector<std::string> found = FoundTerms(equation);
  StructureScore s;
  s.found = static_cast<int>(found.size());
  s.truth = static_cast<int>(truth.size());
  for (const std::string& t : found)
    s.correct += std::find(truth.begin(), truth.end(), t) != truth.end();
  s.precision = s.found > 0 ? static_cast<double>(s.correct) / s.found : 0.0;
  s.recall = s.truth > 0 ? static_cast<double>(s.correct) / s.truth : 0.0;
  return s;
}

std::optional<std::vector<std::string>> TrueTerms(const std::string& vessel,
                                                  const std::string& state) {
  // In Expression::Terms' normal form (factors sorted).
  static const std::map<std::pair<std::string, std::string>, std::vector<std::string>> kTruth = {
      {{"msd", "v"}, {"f", "v", "x"}},
      {{"odin3dof", "u"}, {"r*v", "u", "abs(u)*u", "tau_x"}},
      {{"odin3dof", "v"}, {"r*u", "v", "abs(v)*v", "tau_y"}},
      {{"odin3dof", "r"}, {"v", "r", "abs(r)*r", "tau_n"}},
  };
  const auto it = kTruth.find({vessel, state});
  if (it == kTruth.end()) return std::nullopt;
  return it->second;
}

int TermCount(const std::string& equation) { return static_cast<int>(FoundTerms(equation).size()); }

}  // namespace usvid
