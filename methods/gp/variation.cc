#include "methods/gp/variation.h"

#include "methods/gp/ols.h"

namespace usvid::gp {
namespace {

uint64_t SplitMix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

Node Terminal(Rng& rng, const PrimitiveSet& set) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (unit(rng) < set.constant_probability)
    return {Op::kConst, 0, 1, std::uniform_real_distribution<double>(-1.0, 1.0)(rng)};
  return {Op::kVar, static_cast<uint16_t>(rng() % set.variables), 1, 0.0};
}

void Grow(Rng& rng, const PrimitiveSet& set, int depth, bool full, Tree& out) {
  const size_t terminals = static_cast<size_t>(set.variables) + 1;
  const bool leaf = depth <= 1 || set.functions.empty() ||
                    (!full && rng() % (terminals + set.functions.size()) < terminals);
  if (leaf) {
    out.push_back(Terminal(rng, set));
    return;
  }
  const Op op = set.functions[rng() % set.functions.size()];
  for (int k = 0; k < Arity(op); ++k) Grow(rng, set, depth - 1, full, out);
  out.push_back({op, 0, 1, 0.0});
}

// A node index, internal nodes 90 % of the time when there are any (Koza).
int PickNode(Rng& rng, const Tree& t) {
  std::vector<int> internal;
  for (int i = 0; i < static_cast<int>(t.size()); ++i)
    if (Arity(t[i].op) > 0) internal.push_back(i);
  if (!internal.empty() && rng() % 10 != 0) return internal[rng() % internal.size()];
  return static_cast<int>(rng() % t.size());
}

Tree Splice(const Tree& a, int at, const Tree& b, int from) {
  const int a_start = at + 1 - a[at].length;
  const int b_start = from + 1 - b[from].length;
  Tree out(a.begin(), a.begin() + a_start);
  out.insert(out.end(), b.begin() + b_start, b.begin() + from + 1);
  out.insert(out.end(), a.begin() + at + 1, a.end());
  UpdateLengths(out);
  return out;
}

}  // namespace

Rng StreamFor(uint64_t seed, uint64_t generation, uint64_t index) {
  return Rng(SplitMix64(SplitMix64(SplitMix64(seed) ^ generation) ^ index));
}

Tree RandomTree(Rng& rng, const PrimitiveSet& set, int depth, bool full) {
  Tree t;
  Grow(rng, set, depth, full, t);
  UpdateLengths(t);
  return t;
}

Tree Crossover(Rng& rng, const Tree& a, const Tree& b, int max_depth) {
  for (int attempt = 0; attempt < 5; ++attempt) {
    Tree child = Splice(a, PickNode(rng, a), b, PickNode(rng, b));
    if (Depth(child) <= max_depth && child.size() < 1000) return child;
  }
  return a;
}

Tree Mutate(Rng& rng, const Tree& tree, const PrimitiveSet& set, int max_depth) {
  if (rng() % 2 == 0) {
    for (int attempt = 0; attempt < 5; ++attempt) {
      const Tree fresh = RandomTree(rng, set, 1 + static_cast<int>(rng() % 3), false);
      Tree child = Splice(tree, static_cast<int>(rng() % tree.size()), fresh,
                          static_cast<int>(fresh.size()) - 1);
      if (Depth(child) <= max_depth && child.size() < 1000) return child;
    }
    return tree;
  }
  Tree child = tree;
  Node& n = child[rng() % child.size()];
  if (Arity(n.op) == 0) {
    const uint16_t length = n.length;
    n = Terminal(rng, set);
    n.length = length;
  } else {
    std::vector<Op> same;
    for (Op op : set.functions)
      if (Arity(op) == Arity(n.op)) same.push_back(op);
    if (!same.empty()) n.op = same[rng() % same.size()];
  }
  return child;
}

namespace {

// `term` added to the sum of `tree`, or in place of one of its terms, within `max_depth`.
Tree AddOrReplaceTerm(Rng& rng, const Tree& tree, const Tree& term, int term_root, int max_depth) {
  const int start = term_root + 1 - term[term_root].length;
  Tree sum = tree;
  sum.insert(sum.end(), term.begin() + start, term.begin() + term_root + 1);
  sum.push_back({Op::kAdd, 0, 1, 0.0});
  UpdateLengths(sum);
  if (Depth(sum) <= max_depth && sum.size() < 1000) return sum;
  const std::vector<int> terms = SplitTerms(tree);
  Tree child = Splice(tree, terms[rng() % terms.size()], term, term_root);
  return Depth(child) <= max_depth && child.size() < 1000 ? child : tree;
}

}  // namespace

Tree MutateTerm(Rng& rng, const Tree& tree, const PrimitiveSet& set, int max_depth) {
  const Tree term = RandomTree(rng, set, 2 + static_cast<int>(rng() % 2), false);
  return AddOrReplaceTerm(rng, tree, term, static_cast<int>(term.size()) - 1, max_depth);
}

Tree CrossoverTerms(Rng& rng, const Tree& a, const Tree& b, int max_depth) {
  const std::vector<int> terms = SplitTerms(b);
  return AddOrReplaceTerm(rng, a, b, terms[rng() % terms.size()], max_depth);
}

}  // namespace usvid::gp
