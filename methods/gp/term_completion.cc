#include "methods/gp/term_completion.h"

#include <algorithm>
#include <set>
#include <string>

#include "methods/gp/ols.h"

namespace usvid::gp {

std::vector<Tree> CompletionLibrary(const std::vector<int>& states,
                                    const std::vector<int>& features,
                                    const std::vector<Op>& functions) {
  auto leaf = [](int var) { return Node{Op::kVar, static_cast<uint16_t>(var), 1, 0.0}; };
  std::vector<Tree> library;
  for (int f : features) library.push_back({leaf(f)});
  if (std::find(functions.begin(), functions.end(), Op::kMul) != functions.end())
    for (size_t i = 0; i < states.size(); ++i)
      for (size_t j = i; j < states.size(); ++j)
        library.push_back({leaf(states[i]), leaf(states[j]), Node{Op::kMul, 0, 3, 0.0}});
  return library;
}

Model CompleteTerms(const Model& model, const std::vector<Tree>& library, const GpProblem& problem,
                    const GpOptions& options) {
  Tree tree = model.tree;
  std::set<std::string> present;
  for (int root : SplitTerms(tree)) {
    const Tree term(tree.begin() + root + 1 - tree[root].length, tree.begin() + root + 1);
    present.insert(ToString(term, problem.names));
  }
  for (const Tree& term : library) {
    if (!present.insert(ToString(term, problem.names)).second) continue;
    tree.insert(tree.end(), term.begin(), term.end());
    tree.push_back({Op::kAdd, 0, 1, 0.0});
  }
  UpdateLengths(tree);
  return FitTree(tree, problem, options);
}

}  // namespace usvid::gp
