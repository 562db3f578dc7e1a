// Whether an identified equation has the true structure: its additive terms (Expression::Terms,
// products normalised, coefficients dropped; the constant term ignored on both sides, an offset
// is not structure) against the true terms. precision = correct / found, recall = correct /
// true. True terms are known for msd and odin3dof (docs/model.md#msd, docs/model.md#odin3dof).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace usvid {

struct StructureScore {
  double precision = 0.0, recall = 0.0;
  int found = 0, correct = 0, truth = 0;
};

// Throws InputError when `equation` does not parse.
StructureScore ScoreStructure(const std::string& equation, const std::vector<std::string>& truth);

// The true terms of a state's derivative, or nothing when the vessel's are not known.
std::optional<std::vector<std::string>> TrueTerms(const std::string& vessel,
                                                  const std::string& state);

// The number of additive terms (complexity) of an equation, the constant excluded.
int TermCount(const std::string& equation);

}  // namespace usvid
