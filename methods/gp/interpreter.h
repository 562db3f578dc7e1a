// Evaluates a postfix tree over a batch of rows (Operon's batch interpreter): one buffer
// column of kBatch values per node, each node computed from its children's columns in one
// vectorisable loop, so dispatch costs once per node and batch, not per row. T is float or
// double. The buffer belongs to the interpreter: use one interpreter per thread.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/gp/tree.h"

namespace usvid::gp {

template <typename T>
class Interpreter {
 public:
  static constexpr int kBatch = 256;

  // `columns[v]` points at the rows of variable v.
  explicit Interpreter(std::vector<const T*> columns) : columns_(std::move(columns)) {}

  // Evaluates every node of `tree` for rows [begin, begin + count), count <= kBatch; node i's
  // values are at Column(i).
  void Evaluate(const Tree& tree, long begin, int count) {
    if (buffer_.size() < tree.size() * kBatch) buffer_.resize(tree.size() * kBatch);
    for (size_t i = 0; i < tree.size(); ++i) {
      const Node& n = tree[i];
      T* out = buffer_.data() + i * kBatch;
      const T* a = nullptr;
      const T* b = nullptr;
      if (Arity(n.op) == 2) {
        b = buffer_.data() + (i - 1) * kBatch;
        a = buffer_.data() + (i - 1 - tree[i - 1].length) * kBatch;
      } else if (Arity(n.op) == 1) {
        a = buffer_.data() + (i - 1) * kBatch;
      }
      switch (n.op) {
        case Op::kConst:
          std::fill(out, out + count, static_cast<T>(n.value));
          break;
        case Op::kVar:
          std::copy(columns_[n.var] + begin, columns_[n.var] + begin + count, out);
          break;
        case Op::kAdd:
          for (int r = 0; r < count; ++r) out[r] = a[r] + b[r];
          break;
        case Op::kSub:
          for (int r = 0; r < count; ++r) out[r] = a[r] - b[r];
          break;
        case Op::kMul:
          for (int r = 0; r < count; ++r) out[r] = a[r] * b[r];
          break;
        case Op::kDiv:
          for (int r = 0; r < count; ++r)
            out[r] = std::abs(b[r]) < static_cast<T>(1e-12) ? a[r] : a[r] / b[r];
          break;
        case Op::kAbs:
          for (int r = 0; r < count; ++r) out[r] = std::abs(a[r]);
          break;
        case Op::kTanh:
          for (int r = 0; r < count; ++r) out[r] = std::tanh(a[r]);
          break;
        case Op::kSin:
          for (int r = 0; r < count; ++r) out[r] = std::sin(a[r]);
          break;
        case Op::kCos:
          for (int r = 0; r < count; ++r) out[r] = std::cos(a[r]);
          break;
        case Op::kExp:
          for (int r = 0; r < count; ++r) out[r] = std::exp(std::min(a[r], static_cast<T>(50)));
          break;
        case Op::kSqrt:
          for (int r = 0; r < count; ++r) out[r] = std::sqrt(std::abs(a[r]));
          break;
      }
    }
  }

  const T* Column(int node) const { return buffer_.data() + static_cast<size_t>(node) * kBatch; }

 private:
  std::vector<const T*> columns_;
  std::vector<T> buffer_;
};

}  // namespace usvid::gp
