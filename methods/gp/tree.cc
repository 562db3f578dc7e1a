#include "methods/gp/tree.h"

#include <algorithm>
#include <sstream>

#include "core/parse_number.h"

namespace usvid::gp {

int Arity(Op op) {
  switch (op) {
    case Op::kConst:
    case Op::kVar:
      return 0;
    case Op::kAdd:
    case Op::kSub:
    case Op::kMul:
    case Op::kDiv:
      return 2;
    default:
      return 1;
  }
}

const char* Symbol(Op op) {
  switch (op) {
    case Op::kAdd:
      return "+";
    case Op::kSub:
      return "-";
    case Op::kMul:
      return "*";
    case Op::kDiv:
      return "/";
    case Op::kAbs:
      return "abs";
    case Op::kTanh:
      return "tanh";
    case Op::kSin:
      return "sin";
    case Op::kCos:
      return "cos";
    case Op::kExp:
      return "exp";
    case Op::kSqrt:
      return "sqrt";
    default:
      return "";
  }
}

void UpdateLengths(Tree& tree) {
  std::vector<int> stack;
  for (size_t i = 0; i < tree.size(); ++i) {
    int length = 1;
    for (int k = 0; k < Arity(tree[i].op); ++k) {
      length += stack.back();
      stack.pop_back();
    }
    tree[i].length = static_cast<uint16_t>(length);
    stack.push_back(length);
  }
}

std::vector<int> Children(const Tree& tree, int i) {
  std::vector<int> children;
  int child = i - 1;
  for (int k = 0; k < Arity(tree[i].op); ++k) {
    children.push_back(child);
    child -= tree[child].length;
  }
  std::reverse(children.begin(), children.end());
  return children;
}

int Depth(const Tree& tree, int i) {
  int depth = 0;
  for (int c : Children(tree, i)) depth = std::max(depth, Depth(tree, c));
  return depth + 1;
}

std::string ToString(const Tree& tree, int i, const std::vector<std::string>& names) {
  const Node& n = tree[i];
  std::ostringstream s;
  if (n.op == Op::kConst) {
    if (n.value < 0) {
      s << '(' << FormatNumber(n.value) << ')';
    } else {
      s << FormatNumber(n.value);
    }
  } else if (n.op == Op::kVar) {
    s << names[n.var];
  } else {
    const std::vector<int> c = Children(tree, i);
    if (Arity(n.op) == 1) {
      s << Symbol(n.op) << '(' << ToString(tree, c[0], names) << ')';
    } else {
      s << '(' << ToString(tree, c[0], names) << ' ' << Symbol(n.op) << ' '
        << ToString(tree, c[1], names) << ')';
    }
  }
  return s.str();
}

}  // namespace usvid::gp
