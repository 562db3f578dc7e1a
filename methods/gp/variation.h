// Random trees and their variation: ramped half-and-half initialisation, subtree crossover and
// subtree or point mutation, all within a maximum depth. Randomness comes only from the stream
// passed in, so results depend on the seed, never on threads or scheduling.
#pragma once

#include <random>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

struct PrimitiveSet {
  std::vector<Op> functions;  // from --operators
  int variables = 1;
  double constant_probability = 0.1;  // of a terminal being a constant in [-1, 1]
};

using Rng = std::mt19937_64;

// A stream for (seed, generation, index): SplitMix64 of the three.
Rng StreamFor(uint64_t seed, uint64_t generation, uint64_t index);

// `full`: every branch reaches `depth`; otherwise branches may stop early (grow).
Tree RandomTree(Rng& rng, const PrimitiveSet& set, int depth, bool full);

// The child: a copy of `a` with a random subtree replaced by a random subtree of `b`, within
// `max_depth` (a copy of `a` when no such pair is found in a few tries).
Tree Crossover(Rng& rng, const Tree& a, const Tree& b, int max_depth);

// Subtree mutation (a random subtree replaced by a new one of depth <= 3) or point mutation
// (one node changed to another of the same arity), half and half, within `max_depth`.
Tree Mutate(Rng& rng, const Tree& tree, const PrimitiveSet& set, int max_depth);

// Term mutation: a new random term (depth <= 3) added to the tree's top-level sum, or put in
// place of one of its terms when the sum would grow past `max_depth`. GP-OLS weighs and prunes
// terms, so a search over which terms are in the sum is what it needs most.
Tree MutateTerm(Rng& rng, const Tree& tree, const PrimitiveSet& set, int max_depth);

// Term crossover (multi-gene GP's high-level crossover): one of `b`'s terms added to `a`'s sum,
// or put in place of one of `a`'s terms when the sum would grow past `max_depth`. Terms that
// explain little alone can explain much together (in odin3dof's v' = -u r - d(v) + b tau_y the
// terms nearly cancel), so whole terms have to meet in one sum.
Tree CrossoverTerms(Rng& rng, const Tree& a, const Tree& b, int max_depth);

}  // namespace usvid::gp
