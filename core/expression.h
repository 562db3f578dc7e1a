// The equations of model.json (docs/data.md#equation-syntax): parsed once into a flat postfix
// program and evaluated per sample, over a whole Dataset, or on any scalar T (double, ceres::Jet).
//
// Grammar (whitespace between tokens is ignored; columns in messages are 1-based bytes):
//   expression := product (('+' | '-') product)*           left-associative
//   product    := unary (('*' | '/') unary)*               left-associative
//   unary      := '-' unary | primary                      binds tighter than '*' and '/', as in C
//   primary    := number | channel | function '(' expression ')' | '(' expression ')'
//   number     := digits ['.' digits*] [exponent] | '.' digits [exponent]
//                 exponent := ('e' | 'E') ['+' | '-'] digits        e.g. 2.0263e-4, .5, 3.
//   channel    := [A-Za-z_][A-Za-z0-9_]*, other than a function name
//   function   := abs | tanh | sin | cos | exp | sqrt            (one argument each)
// There is no unary '+', no '^' (write powers as repeated products, u*u) and no comma.
//
// Protected semantics (the same in every evaluation, so a GP model means the same everywhere):
//   x / y  = x         when |y| < 1e-12 (protected division, as in GP), x / y otherwise
//   sqrt(x) = sqrt(|x|)
//   exp(x)  = exp(min(x, 50))  (no overflow; as GP's interpreter, methods/gp/interpreter.h)
// Everything else is IEEE arithmetic with the <cmath> functions; NaN propagates.
//
// Parse() throws InputError "<where>: column N: <what>" for an empty text, an unexpected
// character or token, a malformed or out-of-range number, a missing ')', an unknown function, a
// function without parentheses, text after a complete expression, or nesting deeper than 256.
// Evaluate(const Dataset&) throws InputError naming a channel the data lack.
// Sub-expressions made of constants only are folded at parse time when the value is finite
// (bit-identical results). An Expression is immutable after Parse(); its const methods may run
// concurrently.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace usvid {

class Dataset;

enum class OpCode : std::uint8_t {
  kConstant,  // push value
  kVariable,  // push variables[index]
  kNegate,
  kAdd,
  kSubtract,
  kMultiply,
  kDivide,  // protected
  kAbs,
  kTanh,
  kSin,
  kCos,
  kExp,
  kSqrt,  // of |x|
};

struct Instruction {
  OpCode op = OpCode::kConstant;
  int index = 0;       // kVariable: position in Expression::Variables()
  double value = 0.0;  // kConstant
};

inline constexpr double kProtectedDivisionEpsilon = 1e-12;
inline constexpr double kProtectedExpLimit = 50.0;

// The name of a function op ("abs", "tanh", ...); empty for the other ops.
std::string_view FunctionName(OpCode op);

// "c0 + c1*u - c2*abs(v)*v": weights[j] times terms[j] ("1": the weight alone), the zero weights
// left out, each weight written to read back as exactly the same double; "0" when all are zero.
// The equations of linear-in-the-parameters models (sindy, lti) in the equation syntax.
std::string WeightedSumText(const std::vector<std::string>& terms, const Eigen::VectorXd& weights);

// The op applied to x (unary) or to x and y (binary) exactly as evaluation computes it; aborts
// for kConstant and kVariable.
double ApplyOperator(OpCode op, double x, double y = 0.0);

class Expression {
 public:
  // The constant 0.
  Expression();

  static Expression Parse(const std::string& text, const std::string& where = "expression");

  // The channel names the expression uses, sorted, unique.
  const std::vector<std::string>& Variables() const { return variables_; }
  // The postfix program (operands before their operator).
  const std::vector<Instruction>& program() const { return program_; }

  // Value for one sample; variables[i] is the value of Variables()[i] (aborts if the span is
  // shorter). Does not allocate up to a stack depth of kInlineStack (deeper programs, which only
  // heavy right-nesting produces, use one heap buffer per call).
  double Evaluate(std::span<const double> variables) const;
  // Value at every row of `data`, evaluated column-wise in blocks, bit-identical to
  // Evaluate(span) row by row; NaN at rows where a channel the expression uses is not sampled.
  Eigen::VectorXd Evaluate(const Dataset& data) const;
  // Values at `rows` rows given column by column: columns[i] points to the rows' values of
  // Variables()[i], `out` receives one value per row. Evaluated an operator at a time over blocks
  // of rows (one dispatch per operator and block, not per row), bit-identical to Evaluate(span)
  // row by row. Aborts if there are fewer columns than variables.
  void EvaluateColumns(std::span<const double* const> columns, Eigen::Index rows,
                       double* out) const;
  // The same as Evaluate(span) on any scalar with the <cmath> functions found by ADL.
  template <typename T>
  T EvaluateT(const T* variables) const;

  // The expression in the grammar above; Parse(ToString()) evaluates bit-identically.
  std::string ToString() const;

  // The expression expanded into a sum of products, as (term, coefficient) sorted by term; see
  // core/expression_terms.h for the normal form.
  std::vector<std::pair<std::string, double>> Terms() const;

  static constexpr int kInlineStack = 32;

 private:
  // What Run executes: the program with every constant or variable that the next operator takes
  // as its right operand folded into that operator (`x c *` becomes `x *c`). The same operations
  // on the same operands in the same order, so bit-identical to the program, in about half the
  // dispatches: free runs of equation models spend most of their time here.
  enum class Step : std::uint8_t {
    kConstant, kVariable, kNegate, kAdd, kSubtract, kMultiply, kDivide, kAbs, kTanh, kSin, kCos,
    kExp, kSqrt, kAddConstant, kSubtractConstant, kMultiplyConstant, kDivideConstant,
    kAddVariable, kSubtractVariable, kMultiplyVariable, kDivideVariable,
  };

  struct Fused {
    Step op = Step::kConstant;
    int index = 0;       // variables[index]: kVariable and the *Variable steps
    double value = 0.0;  // kConstant and the *Constant steps
  };
  static std::vector<Fused> Fuse(const std::vector<Instruction>& program);

  template <typename T>
  T Run(const T* variables, T* stack) const;

  std::vector<Instruction> program_;
  std::vector<Fused> fused_;
  std::vector<std::string> variables_;
  int max_stack_ = 1;
  std::string where_ = "expression";
};

template <typename T>
T ProtectedDivide(const T& x, const T& y) {
  using std::abs;
  return abs(y) < T(kProtectedDivisionEpsilon) ? x : T(x / y);
}

template <typename T>
T ProtectedSqrt(const T& x) {
  using std::abs;
  using std::sqrt;
  return sqrt(abs(x));
}

template <typename T>
T ProtectedExp(const T& x) {
  using std::exp;
  return exp(T(kProtectedExpLimit) < x ? T(kProtectedExpLimit) : x);  // NaN stays NaN
}

template <typename T>
T Expression::Run(const T* variables, T* stack) const {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::tanh;
  T* top = stack;  // one past the last pushed value
  for (const Fused& in : fused_) {
    switch (in.op) {
      case Step::kConstant:
        *top++ = T(in.value);
        break;
      case Step::kVariable:
        *top++ = variables[in.index];
        break;
      case Step::kNegate:
        top[-1] = -top[-1];
        break;
      case Step::kAdd:
        top[-2] = top[-2] + top[-1];
        --top;
        break;
      case Step::kSubtract:
        top[-2] = top[-2] - top[-1];
        --top;
        break;
      case Step::kMultiply:
        top[-2] = top[-2] * top[-1];
        --top;
        break;
      case Step::kDivide:
        top[-2] = ProtectedDivide(top[-2], top[-1]);
        --top;
        break;
      case Step::kAbs:
        top[-1] = abs(top[-1]);
        break;
      case Step::kTanh:
        top[-1] = tanh(top[-1]);
        break;
      case Step::kSin:
        top[-1] = sin(top[-1]);
        break;
      case Step::kCos:
        top[-1] = cos(top[-1]);
        break;
      case Step::kExp:
        top[-1] = ProtectedExp(top[-1]);
        break;
      case Step::kSqrt:
        top[-1] = ProtectedSqrt(top[-1]);
        break;
      case Step::kAddConstant:
        top[-1] = top[-1] + T(in.value);
        break;
      case Step::kSubtractConstant:
        top[-1] = top[-1] - T(in.value);
        break;
      case Step::kMultiplyConstant:
        top[-1] = top[-1] * T(in.value);
        break;
      case Step::kDivideConstant:
        top[-1] = ProtectedDivide(top[-1], T(in.value));
        break;
      case Step::kAddVariable:
        top[-1] = top[-1] + variables[in.index];
        break;
      case Step::kSubtractVariable:
        top[-1] = top[-1] - variables[in.index];
        break;
      case Step::kMultiplyVariable:
        top[-1] = top[-1] * variables[in.index];
        break;
      case Step::kDivideVariable:
        top[-1] = ProtectedDivide(top[-1], variables[in.index]);
        break;
    }
  }
  return top[-1];
}

template <typename T>
T Expression::EvaluateT(const T* variables) const {
  if (max_stack_ <= kInlineStack) {
    T stack[kInlineStack];
    return Run(variables, stack);
  }
  std::vector<T> stack(static_cast<std::size_t>(max_stack_));
  return Run(variables, stack.data());
}

}  // namespace usvid
