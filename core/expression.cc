#include "core/expression.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <limits>
#include <optional>
#include <string_view>

#include "core/check.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/expression_terms.h"
#include "core/nan.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

constexpr int kMaxNesting = 256;
constexpr Eigen::Index kBlockRows = 256;

struct NamedFunction {
  std::string_view name;
  OpCode op;
};
constexpr std::array<NamedFunction, 6> kFunctions = {{{"abs", OpCode::kAbs},
                                                      {"tanh", OpCode::kTanh},
                                                      {"sin", OpCode::kSin},
                                                      {"cos", OpCode::kCos},
                                                      {"exp", OpCode::kExp},
                                                      {"sqrt", OpCode::kSqrt}}};

const NamedFunction* FindFunction(std::string_view name) {
  for (const NamedFunction& f : kFunctions) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

bool IsIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }

enum class TokenKind { kEnd, kNumber, kName, kPlus, kMinus, kStar, kSlash, kOpen, kClose };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string_view text;
  int column = 0;  // 1-based
  double value = 0.0;
};

std::string Quote(std::string_view text) { return "'" + std::string(text) + "'"; }

std::string DescribeCharacter(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return Quote(std::string_view(&c, 1));
  char buf[16];
  std::snprintf(buf, sizeof buf, "byte 0x%02X",
                static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buf;
}

std::string DescribeToken(const Token& t) {
  return t.kind == TokenKind::kEnd ? "the end of the expression" : Quote(t.text);
}

// Recursive descent straight into postfix; constant operands are folded as they are emitted.
class Parser {
 public:
  Parser(std::string_view text, const std::string& where) : text_(text), where_(where) {}

  void Run() {
    Advance();
    if (token_.kind == TokenKind::kEnd) Fail(token_.column, "empty expression");
    ParseSum();
    if (token_.kind != TokenKind::kEnd)
      Fail(token_.column, "unexpected " + DescribeToken(token_) + " after a complete expression");
  }

  std::vector<Instruction>& program() { return program_; }
  std::vector<std::string>& names() { return names_; }

 private:
  [[noreturn]] void Fail(int column, const std::string& what) const {
    throw InputError(where_ + ": column " + std::to_string(column) + ": " + what);
  }

  void Advance() {
    std::size_t i = pos_;
    while (i < text_.size() &&
           (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\n' || text_[i] == '\r')) {
      ++i;
    }
    token_ = Token{};
    token_.column = static_cast<int>(i) + 1;
    if (i == text_.size()) {
      pos_ = i;
      return;
    }
    const char c = text_[i];
    std::size_t end = i + 1;
    switch (c) {
      case '+':
        token_.kind = TokenKind::kPlus;
        break;
      case '-':
        token_.kind = TokenKind::kMinus;
        break;
      case '*':
        token_.kind = TokenKind::kStar;
        break;
      case '/':
        token_.kind = TokenKind::kSlash;
        break;
      case '(':
        token_.kind = TokenKind::kOpen;
        break;
      case ')':
        token_.kind = TokenKind::kClose;
        break;
      default:
        if (IsIdentifierStart(c)) {
          while (end < text_.size() && IsIdentifierChar(text_[end])) ++end;
          token_.kind = TokenKind::kName;
        } else if (IsDigit(c) || c == '.') {
          end = ScanNumber(i);
          token_.kind = TokenKind::kNumber;
        } else if (c == '^') {
          Fail(token_.column, "unexpected '^': powers are not supported, write u*u");
        } else {
          Fail(token_.column, "unexpected character " + DescribeCharacter(c));
        }
    }
    token_.text = text_.substr(i, end - i);
    pos_ = end;
    if (token_.kind == TokenKind::kNumber) {
      const ParsedNumber n = ParseNumber(token_.text);
      if (n.status != NumberStatus::kOk)
        Fail(token_.column, DescribeNumberStatus(n.status, token_.text));
      token_.value = n.value;
    }
  }

  // The end of the number starting at `i`; the digits, point and exponent must form a number
  // that no letter, digit or point directly follows.
  std::size_t ScanNumber(std::size_t i) const {
    const std::size_t start = i;
    std::size_t digits = 0;
    while (i < text_.size() && IsDigit(text_[i])) ++i, ++digits;
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      while (i < text_.size() && IsDigit(text_[i])) ++i, ++digits;
    }
    bool ok = digits > 0;
    if (ok && i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      ++i;
      if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
      std::size_t exponent_digits = 0;
      while (i < text_.size() && IsDigit(text_[i])) ++i, ++exponent_digits;
      ok = exponent_digits > 0;
    }
    if (!ok || (i < text_.size() && (IsIdentifierChar(text_[i]) || text_[i] == '.'))) {
      while (i < text_.size() && (IsIdentifierChar(text_[i]) || text_[i] == '.')) ++i;
      Fail(static_cast<int>(start) + 1,
           "malformed number " + Quote(text_.substr(start, i - start)));
    }
    return i;
  }

  void Enter(int column) {
    if (++depth_ > kMaxNesting)
      Fail(column, "nested deeper than " + std::to_string(kMaxNesting) + " levels");
  }

  void ParseSum() {
    ParseProduct();
    while (token_.kind == TokenKind::kPlus || token_.kind == TokenKind::kMinus) {
      const OpCode op = token_.kind == TokenKind::kPlus ? OpCode::kAdd : OpCode::kSubtract;
      Advance();
      ParseProduct();
      EmitBinary(op);
    }
  }

  void ParseProduct() {
    ParseUnary();
    while (token_.kind == TokenKind::kStar || token_.kind == TokenKind::kSlash) {
      const OpCode op = token_.kind == TokenKind::kStar ? OpCode::kMultiply : OpCode::kDivide;
      Advance();
      ParseUnary();
      EmitBinary(op);
    }
  }

  void ParseUnary() {
    if (token_.kind != TokenKind::kMinus) return ParsePrimary();
    Enter(token_.column);
    Advance();
    ParseUnary();
    EmitUnary(OpCode::kNegate);
    --depth_;
  }

  void ParsePrimary() {
    const Token t = token_;
    switch (t.kind) {
      case TokenKind::kNumber:
        program_.push_back({OpCode::kConstant, 0, t.value});
        Advance();
        return;
      case TokenKind::kName: {
        Advance();
        const NamedFunction* f = FindFunction(t.text);
        if (token_.kind == TokenKind::kOpen) {
          if (f == nullptr)
            Fail(t.column,
                 "unknown function " + Quote(t.text) + " (known: abs, tanh, sin, cos, exp, sqrt)");
          ParseParenthesised();
          EmitUnary(f->op);
        } else if (f != nullptr) {
          Fail(t.column, "function " + Quote(t.text) + " needs parentheses, e.g. " +
                             std::string(t.text) + "(u)");
        } else {
          program_.push_back({OpCode::kVariable, NameIndex(t.text), 0.0});
        }
        return;
      }
      case TokenKind::kOpen:
        ParseParenthesised();
        return;
      default:
        Fail(t.column, "expected a number, channel, function or '(' but found " + DescribeToken(t));
    }
  }

  void ParseParenthesised() {
    const int open_column = token_.column;
    Enter(open_column);
    Advance();
    ParseSum();
    if (token_.kind != TokenKind::kClose)
      Fail(token_.column, "missing ')' to close '(' at column " + std::to_string(open_column) +
                              ", found " + DescribeToken(token_));
    Advance();
    --depth_;
  }

  int NameIndex(std::string_view name) {
    const auto it = std::find(names_.begin(), names_.end(), name);
    if (it != names_.end()) return static_cast<int>(it - names_.begin());
    names_.emplace_back(name);
    return static_cast<int>(names_.size()) - 1;
  }

  void EmitUnary(OpCode op) {
    program_.push_back({op, 0, 0.0});
    FoldConstants(1);
  }

  void EmitBinary(OpCode op) {
    program_.push_back({op, 0, 0.0});
    FoldConstants(2);
  }

  // When the operator just emitted has only constant operands, replaces them by their value
  // if it is finite.
  void FoldConstants(std::size_t operands) {
    const std::size_t n = program_.size();
    for (std::size_t k = 2; k <= operands + 1; ++k) {
      if (program_[n - k].op != OpCode::kConstant) return;
    }
    const OpCode op = program_[n - 1].op;
    const double value = operands == 1
                             ? ApplyOperator(op, program_[n - 2].value, 0.0)
                             : ApplyOperator(op, program_[n - 3].value, program_[n - 2].value);
    if (!std::isfinite(value)) return;  // a number text cannot hold it
    program_.resize(n - operands - 1);
    program_.push_back({OpCode::kConstant, 0, value});
  }

  std::string_view text_;
  const std::string& where_;
  std::size_t pos_ = 0;
  Token token_;
  int depth_ = 0;
  std::vector<Instruction> program_;
  std::vector<std::string> names_;
};

int MaxStack(const std::vector<Instruction>& program) {
  int depth = 0;
  int max_depth = 1;
  for (const Instruction& in : program) {
    switch (in.op) {
      case OpCode::kConstant:
      case OpCode::kVariable:
        max_depth = std::max(max_depth, ++depth);
        break;
      case OpCode::kAdd:
      case OpCode::kSubtract:
      case OpCode::kMultiply:
      case OpCode::kDivide:
        --depth;
        break;
      default:
        break;
    }
  }
  return max_depth;
}

// Operator levels for printing: a sum < a product < a unary minus < a primary.
constexpr int kSumLevel = 1;
constexpr int kProductLevel = 2;
constexpr int kUnaryLevel = 3;
constexpr int kPrimaryLevel = 4;

struct Printed {
  std::string text;
  int level = kPrimaryLevel;
  bool negative_constant = false;
  double value = 0.0;
};

std::string Parenthesised(const Printed& p, bool parenthesise) {
  return parenthesise ? "(" + p.text + ")" : p.text;
}

Printed PrintBinary(OpCode op, const Printed& left, Printed right) {
  const bool sum = op == OpCode::kAdd || op == OpCode::kSubtract;
  const int level = sum ? kSumLevel : kProductLevel;
  if (sum && right.negative_constant) {
    // x + (-c) and x - c are the same IEEE operation, and likewise x - (-c) and x + c.
    op = op == OpCode::kAdd ? OpCode::kSubtract : OpCode::kAdd;
    right = {FormatNumber(-right.value), kPrimaryLevel, false, -right.value};
  }
  std::string symbol;
  switch (op) {
    case OpCode::kAdd:
      symbol = " + ";
      break;
    case OpCode::kSubtract:
      symbol = " - ";
      break;
    case OpCode::kMultiply:
      symbol = "*";
      break;
    default:
      symbol = "/";
      break;
  }
  return {Parenthesised(left, left.level < level) + symbol +
              Parenthesised(right, right.level <= level || right.text.front() == '-'),
          level};
}

}  // namespace

std::string_view FunctionName(OpCode op) {
  for (const NamedFunction& f : kFunctions) {
    if (f.op == op) return f.name;
  }
  return {};
}

double ApplyOperator(OpCode op, double x, double y) {
  switch (op) {
    case OpCode::kConstant:
    case OpCode::kVariable:
      break;
    case OpCode::kNegate:
      return -x;
    case OpCode::kAdd:
      return x + y;
    case OpCode::kSubtract:
      return x - y;
    case OpCode::kMultiply:
      return x * y;
    case OpCode::kDivide:
      return ProtectedDivide(x, y);
    case OpCode::kAbs:
      return std::abs(x);
    case OpCode::kTanh:
      return std::tanh(x);
    case OpCode::kSin:
      return std::sin(x);
    case OpCode::kCos:
      return std::cos(x);
    case OpCode::kExp:
      return ProtectedExp(x);
    case OpCode::kSqrt:
      return ProtectedSqrt(x);
  }
  USVID_UNREACHABLE("every function is handled above");
}

Expression::Expression() : program_{{OpCode::kConstant, 0, 0.0}}, fused_(Fuse(program_)) {}

std::vector<Expression::Fused> Expression::Fuse(const std::vector<Instruction>& program) {
  // The binary operators, and the step of each with its right operand a constant or a variable.
  auto fused_op = [](OpCode op, bool constant) -> std::optional<Step> {
    switch (op) {
      case OpCode::kAdd:
        return constant ? Step::kAddConstant : Step::kAddVariable;
      case OpCode::kSubtract:
        return constant ? Step::kSubtractConstant : Step::kSubtractVariable;
      case OpCode::kMultiply:
        return constant ? Step::kMultiplyConstant : Step::kMultiplyVariable;
      case OpCode::kDivide:
        return constant ? Step::kDivideConstant : Step::kDivideVariable;
      default:
        return std::nullopt;
    }
  };
  static_assert(static_cast<int>(Step::kSqrt) == static_cast<int>(OpCode::kSqrt),
                "the steps begin with the op codes, in their order");
  std::vector<Fused> out;
  out.reserve(program.size());
  for (std::size_t i = 0; i < program.size(); ++i) {
    const Instruction& in = program[i];
    const bool operand = in.op == OpCode::kConstant || in.op == OpCode::kVariable;
    // A binary operator right after a push takes the pushed value as its right operand; its left
    // operand is then on the stack already, as the program is well formed.
    if (operand && i + 1 < program.size() && i > 0) {
      if (const auto op = fused_op(program[i + 1].op, in.op == OpCode::kConstant)) {
        out.push_back({*op, in.index, in.value});
        ++i;
        continue;
      }
    }
    out.push_back({static_cast<Step>(in.op), in.index, in.value});
  }
  return out;
}

Expression Expression::Parse(const std::string& text, const std::string& where) {
  Parser parser(text, where);
  parser.Run();
  Expression e;
  e.where_ = where;
  e.program_ = std::move(parser.program());
  const std::vector<std::string>& names = parser.names();
  e.variables_ = names;
  std::sort(e.variables_.begin(), e.variables_.end());
  for (Instruction& in : e.program_) {
    if (in.op != OpCode::kVariable) continue;
    const auto it = std::lower_bound(e.variables_.begin(), e.variables_.end(),
                                     names[static_cast<std::size_t>(in.index)]);
    in.index = static_cast<int>(it - e.variables_.begin());
  }
  e.max_stack_ = MaxStack(e.program_);
  e.fused_ = Fuse(e.program_);
  return e;
}

double Expression::Evaluate(std::span<const double> variables) const {
  USVID_CHECK(variables.size() >= variables_.size(), "a value for every variable");
  return EvaluateT(variables.data());
}

Eigen::VectorXd Expression::Evaluate(const Dataset& data) const {
  std::vector<const Channel*> channels;
  channels.reserve(variables_.size());
  for (const std::string& name : variables_) {
    const Channel* channel = data.Find(name);
    if (channel == nullptr) {
      data.CheckNotText(name);
      throw InputError(where_ + ": channel " + Quote(name) + " is not in the data");
    }
    channels.push_back(channel);
  }
  const Eigen::Index rows = data.rows();
  Eigen::VectorXd result(rows);
  std::vector<const double*> columns(channels.size());
  for (Eigen::Index start = 0; start < rows; start += kBlockRows) {
    const Eigen::Index n = std::min(kBlockRows, rows - start);
    for (std::size_t i = 0; i < channels.size(); ++i)
      columns[i] = channels[i]->values().data() + start;
    EvaluateColumns(columns, n, result.data() + start);
  }
  for (const Channel* channel : channels) {
    if (!channel->FullySampled()) result = channel->sampled().select(result.array(), kNaN).matrix();
  }
  return result;
}

void Expression::EvaluateColumns(std::span<const double* const> columns, Eigen::Index rows,
                                 double* out) const {
  USVID_CHECK(columns.size() >= variables_.size(), "a column for every variable");
  Eigen::ArrayXXd stack(std::min(kBlockRows, std::max<Eigen::Index>(rows, 1)), max_stack_);
  for (Eigen::Index start = 0; start < rows; start += kBlockRows) {
    const Eigen::Index n = std::min(kBlockRows, rows - start);
    Eigen::Index top = -1;
    const auto column = [&](Eigen::Index k) { return stack.col(k).head(n); };
    for (const Instruction& in : program_) {
      switch (in.op) {
        case OpCode::kConstant:
          column(++top).setConstant(in.value);
          break;
        case OpCode::kVariable:
          column(++top) = Eigen::Map<const Eigen::ArrayXd>(
              columns[static_cast<std::size_t>(in.index)] + start, n);
          break;
        case OpCode::kNegate:
          column(top) = -column(top);
          break;
        case OpCode::kAdd:
          column(top - 1) += column(top);
          --top;
          break;
        case OpCode::kSubtract:
          column(top - 1) -= column(top);
          --top;
          break;
        case OpCode::kMultiply:
          column(top - 1) *= column(top);
          --top;
          break;
        case OpCode::kDivide:
          column(top - 1) = (column(top).abs() < kProtectedDivisionEpsilon)
                                .select(column(top - 1), column(top - 1) / column(top));
          --top;
          break;
        case OpCode::kAbs:
          column(top) = column(top).abs();
          break;
        // The <cmath> functions, not Eigen's vectorised approximations, so that rows agree with
        // Evaluate(span) bit for bit.
        case OpCode::kTanh:
          column(top) = column(top).unaryExpr([](double x) { return std::tanh(x); });
          break;
        case OpCode::kSin:
          column(top) = column(top).unaryExpr([](double x) { return std::sin(x); });
          break;
        case OpCode::kCos:
          column(top) = column(top).unaryExpr([](double x) { return std::cos(x); });
          break;
        case OpCode::kExp:
          column(top) = column(top).unaryExpr([](double x) { return ProtectedExp(x); });
          break;
        case OpCode::kSqrt:
          column(top) = column(top).abs().sqrt();
          break;
      }
    }
    Eigen::Map<Eigen::ArrayXd>(out + start, n) = column(0);
  }
}

std::string Expression::ToString() const {
  std::vector<Printed> stack;
  for (const Instruction& in : program_) {
    switch (in.op) {
      case OpCode::kConstant: {
        const bool negative = std::signbit(in.value);
        stack.push_back(
            {FormatNumber(in.value), negative ? kUnaryLevel : kPrimaryLevel, negative, in.value});
        break;
      }
      case OpCode::kVariable:
        stack.push_back({variables_[static_cast<std::size_t>(in.index)]});
        break;
      case OpCode::kNegate:
        stack.back() = {"-" + Parenthesised(stack.back(), stack.back().level < kPrimaryLevel),
                        kUnaryLevel};
        break;
      case OpCode::kAdd:
      case OpCode::kSubtract:
      case OpCode::kMultiply:
      case OpCode::kDivide: {
        Printed right = std::move(stack.back());
        stack.pop_back();
        stack.back() = PrintBinary(in.op, stack.back(), std::move(right));
        break;
      }
      default:
        stack.back() = {std::string(FunctionName(in.op)) + "(" + stack.back().text + ")"};
        break;
    }
  }
  return stack.back().text;
}

std::vector<std::pair<std::string, double>> Expression::Terms() const {
  return ExpandTerms(program_, variables_);
}

std::string WeightedSumText(const std::vector<std::string>& terms, const Eigen::VectorXd& weights) {
  std::string s;
  for (Eigen::Index j = 0; j < weights.size(); ++j) {
    const double w = weights(j);
    if (w == 0.0) continue;
    const std::string& name = terms[static_cast<size_t>(j)];
    const std::string term = FormatNumber(std::abs(w)) + (name == "1" ? "" : "*" + name);
    if (s.empty())
      s = (w < 0 ? "-" : "") + term;
    else
      s += (w < 0 ? " - " : " + ") + term;
  }
  return s.empty() ? "0" : s;
}

}  // namespace usvid
