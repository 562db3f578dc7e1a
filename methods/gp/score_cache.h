// The scores of the trees a search has bred in its last few generations, keyed by the tree
// itself. Tournament selection breeds the same trees again and again: an offspring that was
// neither crossed over nor mutated (7 % at the default rates), a crossover that swaps equal
// subtrees, a term added that was already there. On a default odin-hs search 45-58 % of the
// offspring were trees already scored. Scoring is a pure function of the tree (the rows and the
// options are fixed for a search), so a cached score is the score, bit for bit, and a search
// gives the same result with the cache as without it.
#pragma once

#include <cstddef>
#include <unordered_map>

#include "methods/gp/search.h"
#include "methods/gp/tree.h"

namespace usvid::gp {

class ScoreCache {
 public:
  // Entries not bred again within `keep_generations` are dropped by Forget.
  explicit ScoreCache(int keep_generations) : keep_(keep_generations) {}

  // The score of `tree`, bred again in `generation`, or nullptr.
  const Model* Find(const Tree& tree, int generation);
  void Insert(const Tree& tree, const Model& model, int generation);
  // Drops the entries last bred before generation - keep_generations.
  void Forget(int generation);
  size_t size() const { return entries_.size(); }

  // A tree's hash and equality, for any map keyed by trees.
  struct Hash {
    size_t operator()(const Tree& tree) const;
  };
  struct Equal {
    bool operator()(const Tree& a, const Tree& b) const;
  };

 private:
  struct Entry {
    Model model;
    int last_bred = 0;
  };
  int keep_;
  std::unordered_map<Tree, Entry, Hash, Equal> entries_;
};

}  // namespace usvid::gp
