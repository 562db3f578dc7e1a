#include "methods/gp/astern_symmetry.h"

#include "methods/gp/ols.h"

namespace usvid::gp {

namespace {

bool Reads(const Tree& tree, int root, int var) {
  for (int i = root + 1 - tree[root].length; i <= root; ++i)
    if (tree[i].op == Op::kVar && tree[i].var == var) return true;
  return false;
}

}  // namespace

Tree AsternSymmetric(const Tree& tree, int surge, int self) {
  if (surge == self || tree.empty()) return tree;
  // the terms that read `self`: each a range [first, root] of the postfix array
  std::vector<bool> in_damping_term(tree.size(), false);
  for (const int root : SplitTerms(tree))
    if (Reads(tree, root, self))
      for (int i = root + 1 - tree[root].length; i <= root; ++i) in_damping_term[i] = true;
  Tree out;
  out.reserve(tree.size() + 4);
  for (size_t i = 0; i < tree.size(); ++i) {
    out.push_back(tree[i]);
    const bool wrapped =
        i + 1 < tree.size() && tree[i + 1].op == Op::kAbs;  // abs's child ends at i
    if (in_damping_term[i] && tree[i].op == Op::kVar && tree[i].var == surge && !wrapped)
      out.push_back({Op::kAbs, 0, 2, 0.0});
  }
  UpdateLengths(out);
  return out;
}

}  // namespace usvid::gp
