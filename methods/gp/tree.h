// GP expression trees as flat postfix arrays (Operon's layout): children come before their
// parent, the last node is the root, and each node stores the length of its subtree, so the
// subtree rooted at i is [i + 1 - length, i] and sibling subtrees are found by skipping lengths.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace usvid::gp {

enum class Op : uint8_t {
  kConst,
  kVar,
  kAdd,
  kSub,
  kMul,
  kDiv,  // protected: a / b, or a where |b| < 1e-12
  kAbs,
  kTanh,
  kSin,
  kCos,
  kExp,   // protected: argument clipped at 50
  kSqrt,  // protected: sqrt(|a|)
};

int Arity(Op op);
const char* Symbol(Op op);  // "+", "abs", ...

struct Node {
  Op op = Op::kConst;
  uint16_t var = 0;     // kVar: variable index
  uint16_t length = 1;  // nodes in the subtree rooted here, itself included
  double value = 0.0;   // kConst
};

using Tree = std::vector<Node>;

// Recomputes every node's subtree length (after splicing).
void UpdateLengths(Tree& tree);
// Depth of the subtree rooted at i (a leaf has depth 1).
int Depth(const Tree& tree, int i);
inline int Depth(const Tree& tree) {
  return tree.empty() ? 0 : Depth(tree, static_cast<int>(tree.size()) - 1);
}
// Indices of the children of node i, first child first.
std::vector<int> Children(const Tree& tree, int i);
// Infix text of the subtree at i, variables by name (syntax: docs/data.md#equation-syntax).
std::string ToString(const Tree& tree, int i, const std::vector<std::string>& names);
inline std::string ToString(const Tree& tree, const std::vector<std::string>& names) {
  return ToString(tree, static_cast<int>(tree.size()) - 1, names);
}

}  // namespace usvid::gp
