// The equations of model.json (docs/data.md#equation-syntax): parsing with located errors,
// evaluation per sample, per dataset and on Jets, printing that round-trips, term structure.
#include "core/expression.h"

#include <ceres/jet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <new>
#include <random>

#include "core/dataset.h"
#include "core/error.h"

namespace usvid {
namespace {

thread_local bool t_counting = false;
thread_local long t_allocations = 0;

}  // namespace
}  // namespace usvid

// Counts heap allocations while usvid::t_counting is set, to check the per-sample hot path.
// (GCC cannot see that this pair replaces the global one and warns about malloc/free.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t size) {
  if (usvid::t_counting) ++usvid::t_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace usvid {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using Terms = std::map<std::string, double>;

constexpr char kSurge[] = "v*r - 0.010132*u - 0.049240*abs(u)*u + 2.0263e-4*tau_x";
constexpr char kSway[] = "-u*r - 0.040527*v - 0.405268*abs(v)*v + 2.0263e-4*tau_y";
constexpr char kYaw[] = "-0.061210*v - 0.061210*r - 0.142154*abs(r)*r + 4.7783e-5*tau_n";

class ExpressionTest : public ::testing::Test {
 protected:
  // The value of `e` with channels taken from `values` by name.
  static double Eval(const Expression& e, const std::map<std::string, double>& values) {
    std::vector<double> x;
    for (const std::string& name : e.Variables()) x.push_back(values.at(name));
    return e.Evaluate(x);
  }
  static double Eval(const std::string& text, const std::map<std::string, double>& values) {
    return Eval(Expression::Parse(text), values);
  }
  static std::string ErrorOf(const std::string& text) {
    try {
      Expression::Parse(text, "model.json: equation for u");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  static Terms TermsOf(const std::string& text) {
    Terms terms;
    for (const auto& [term, c] : Expression::Parse(text).Terms()) terms[term] = c;
    return terms;
  }
  // Bit-identical, or both NaN.
  static bool Same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) ||
           std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  }

  const std::map<std::string, double> odin_ = {{"u", 2.0},      {"v", 0.5},     {"r", 0.1},
                                               {"tau_x", 1000}, {"tau_y", 200}, {"tau_n", 500}};
};

// The odin3dof equations of docs/model.md#odin3dof give the hand-computed accelerations.
TEST_F(ExpressionTest, EvaluatesOdin3DofEquations) {
  // 0.05 - 0.020264 - 0.19696 + 0.20263
  EXPECT_NEAR(Eval(kSurge, odin_), 0.035406, 1e-12);
  // -0.2 - 0.0202635 - 0.101317 + 0.040526
  EXPECT_NEAR(Eval(kSway, odin_), -0.2810545, 1e-12);
  // -0.030605 - 0.006121 - 0.00142154 + 0.0238915
  EXPECT_NEAR(Eval(kYaw, odin_), -0.01425604, 1e-12);
}

// Products before sums, both left-associative; unary minus binds tighter than '*' as in C.
TEST_F(ExpressionTest, FollowsPrecedenceAndLeftAssociativity) {
  const std::map<std::string, double> x = {{"a", 8}, {"b", 4}, {"c", 2}, {"d", 3}};
  EXPECT_EQ(Eval("a - b - c", x), 2.0);
  EXPECT_EQ(Eval("a / b * c", x), 4.0);
  EXPECT_EQ(Eval("a / b / c", x), 1.0);
  EXPECT_EQ(Eval("a - b*c + d", x), 3.0);
  EXPECT_EQ(Eval("(a - b)*c", x), 8.0);
  EXPECT_EQ(Eval("a*-b", x), -32.0);
  EXPECT_EQ(Eval("--a", x), 8.0);
  EXPECT_EQ(Eval("-a*b - -c", x), -30.0);
  const Expression negated_product = Expression::Parse("-a*b");
  const std::vector<Instruction>& p = negated_product.program();
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[1].op, OpCode::kNegate);
  EXPECT_EQ(p[3].op, OpCode::kMultiply);
}

// '^' is not part of the syntax; the error points at it and says what to write instead.
TEST_F(ExpressionTest, RefusesPowers) {
  EXPECT_THAT(ErrorOf("2^u"), StartsWith("model.json: equation for u: column 2: "));
  EXPECT_THAT(ErrorOf("2^u"), HasSubstr("u*u"));
}

// Every syntax error names the 1-based column of the offending text.
TEST_F(ExpressionTest, SyntaxErrorsNameTheirColumn) {
  struct Case {
    const char* text;
    int column;
    const char* what;
  };
  const Case cases[] = {
      {"", 1, "empty expression"},
      {"   ", 4, "empty expression"},
      {"u +", 4, "found the end of the expression"},
      {"u * * v", 5, "found '*'"},
      {"+u", 1, "found '+'"},
      {"()", 2, "found ')'"},
      {"(u + v", 7, "missing ')' to close '(' at column 1"},
      {"abs(u", 6, "missing ')' to close '(' at column 4"},
      {"foo(u)", 1, "unknown function 'foo'"},
      {"u + abs", 5, "function 'abs' needs parentheses"},
      {"u + abs u", 5, "function 'abs' needs parentheses"},
      {"u v", 3, "unexpected 'v' after a complete expression"},
      {"u)", 2, "unexpected ')' after a complete expression"},
      {"u # v", 3, "unexpected character '#'"},
      {"sin(u, v)", 6, "unexpected character ','"},
      {"1 + 1e", 5, "malformed number '1e'"},
      {"2u", 1, "malformed number '2u'"},
      {"1.2.3", 1, "malformed number '1.2.3'"},
      {"u*.", 3, "malformed number '.'"},
      {"1e999", 1, "out of the range"},
  };
  for (const Case& c : cases) {
    const std::string error = ErrorOf(c.text);
    EXPECT_THAT(error,
                StartsWith("model.json: equation for u: column " + std::to_string(c.column) + ": "))
        << c.text;
    EXPECT_THAT(error, HasSubstr(c.what)) << c.text;
  }
}

// The number forms of the equation syntax (docs/data.md#equation-syntax) read as decimal numbers.
TEST_F(ExpressionTest, ReadsNumberForms) {
  EXPECT_EQ(Eval("2.0263e-4", {}), 2.0263e-4);
  EXPECT_EQ(Eval(".5", {}), 0.5);
  EXPECT_EQ(Eval("3.", {}), 3.0);
  EXPECT_EQ(Eval("1E+2", {}), 100.0);
  EXPECT_EQ(Eval("-1e-400", {}), 0.0);
}

// Nesting is bounded so hostile input cannot exhaust the parser's stack; deep but legal right
// nesting evaluates past the inline stack.
TEST_F(ExpressionTest, BoundsNestingAndEvaluatesDeepPrograms) {
  EXPECT_THAT(ErrorOf(std::string(300, '(') + "u" + std::string(300, ')')),
              HasSubstr("nested deeper than 256"));
  EXPECT_THAT(ErrorOf(std::string(300, '-') + "u"), HasSubstr("nested deeper than 256"));
  std::string text = "u";
  double expected = 1.01;
  for (int i = 0; i < 100; ++i) {
    text = "u*(" + text + ")";
    expected = 1.01 * expected;
  }
  EXPECT_EQ(Eval(text, {{"u", 1.01}}), expected);
}

// Printing in the equation syntax and parsing again gives bit-identical values, and printing
// is then a fixed point; random expressions cover every operator and parenthesisation.
TEST_F(ExpressionTest, ToStringRoundTripsToIdenticalValues) {
  std::mt19937 rng(7);
  const std::vector<std::string> names = {"u", "v", "r", "tau_x"};
  const std::vector<std::string> numbers = {"0.1", "2.0263e-4", ".5",   "3",     "1e-13",
                                            "0",   "1e300",     "7.25", "1/3.0", "0.000203"};
  const std::vector<std::string> functions = {"abs", "tanh", "sin", "cos", "exp", "sqrt"};
  const std::vector<std::string> ops = {" + ", " - ", "*", "/"};
  const auto pick = [&](const std::vector<std::string>& from) {
    return from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)];
  };
  std::function<std::string(int)> random_text = [&](int depth) -> std::string {
    const int kind = depth == 0 ? static_cast<int>(rng() % 2) : static_cast<int>(rng() % 6);
    switch (kind) {
      case 0:
        return pick(names);
      case 1:
        return pick(numbers);
      case 2:
        return "-" + random_text(depth - 1);
      case 3:
        return pick(functions) + "(" + random_text(depth - 1) + ")";
      case 4:
        return "(" + random_text(depth - 1) + ")";
      default:
        return random_text(depth - 1) + pick(ops) + random_text(depth - 1);
    }
  };
  std::vector<std::string> texts = {kSurge,     kSway,     kYaw,     "a - (b - c)", "a + (b + c)",
                                    "a/(b/c)",  "a*(b*c)", "-(a*b)", "-(-a)",       "a - -0.5",
                                    "a + -0.5", "a*-0.5",  "-0*a",   "a - (-b)",    "1/3*a"};
  for (int i = 0; i < 300; ++i) texts.push_back(random_text(5));
  std::normal_distribution<double> value(0.0, 2.0);
  for (const std::string& text : texts) {
    const Expression e = Expression::Parse(text);
    const std::string printed = e.ToString();
    const Expression again = Expression::Parse(printed);
    EXPECT_EQ(again.ToString(), printed) << text;
    ASSERT_EQ(again.Variables(), e.Variables()) << text;
    for (int k = 0; k < 10; ++k) {
      std::vector<double> x;
      for (std::size_t j = 0; j < e.Variables().size(); ++j) x.push_back(value(rng));
      EXPECT_TRUE(Same(e.Evaluate(x), again.Evaluate(x))) << text << " -> " << printed;
    }
  }
}

// The printed form is the readable one a model file carries.
TEST_F(ExpressionTest, PrintsReadableEquations) {
  EXPECT_EQ(Expression::Parse(kSurge).ToString(),
            "v*r - 0.010132*u - 0.04924*abs(u)*u + 0.00020263*tau_x");
  EXPECT_EQ(Expression::Parse(kSway).ToString(),
            "-u*r - 0.040527*v - 0.405268*abs(v)*v + 0.00020263*tau_y");
  EXPECT_EQ(Expression::Parse("a - (b - c)").ToString(), "a - (b - c)");
  EXPECT_EQ(Expression::Parse("a + -0.5").ToString(), "a - 0.5");
  EXPECT_EQ(Expression::Parse("a*-0.5").ToString(), "a*(-0.5)");
  EXPECT_EQ(Expression::Parse("-(a*b)").ToString(), "-(a*b)");
  EXPECT_EQ(Expression::Parse("((tanh((u))))").ToString(), "tanh(u)");
  EXPECT_EQ(Expression().ToString(), "0");
}

// Variables() lists the channel names once each, sorted; functions and numbers are not listed.
TEST_F(ExpressionTest, ListsVariablesSortedAndUnique) {
  EXPECT_EQ(Expression::Parse("v*r + u*v - tau_x + abs(u) + 2").Variables(),
            (std::vector<std::string>{"r", "tau_x", "u", "v"}));
  EXPECT_TRUE(Expression::Parse("exp(1) + 2").Variables().empty());
  EXPECT_TRUE(Expression().Variables().empty());
}

// Division by |y| < 1e-12 returns the numerator, sqrt reads |x| and exp clips its argument at
// 50 (GP's semantics), per sample and per dataset.
TEST_F(ExpressionTest, UsesProtectedSemantics) {
  EXPECT_EQ(Eval("u / v", {{"u", 3}, {"v", 0}}), 3.0);
  EXPECT_EQ(Eval("u / v", {{"u", 3}, {"v", -1e-13}}), 3.0);
  EXPECT_EQ(Eval("u / v", {{"u", 3}, {"v", 2}}), 1.5);
  EXPECT_EQ(Eval("sqrt(u)", {{"u", -4}}), 2.0);
  EXPECT_EQ(Eval("1/0", {}), 1.0);
  EXPECT_EQ(Eval("exp(u)", {{"u", 800}}), std::exp(50.0));
  EXPECT_TRUE(std::isnan(Eval("exp(u)", {{"u", std::numeric_limits<double>::quiet_NaN()}})));
  Dataset data(Eigen::Vector2d(0.0, 1.0));
  data.Set("u", Eigen::Vector2d(3.0, -4.0));
  data.Set("v", Eigen::Vector2d(0.0, 2.0));
  EXPECT_EQ(Expression::Parse("u / v").Evaluate(data), Eigen::Vector2d(3.0, -2.0));
  EXPECT_EQ(Expression::Parse("sqrt(u)").Evaluate(data), Eigen::Vector2d(std::sqrt(3.0), 2.0));
  EXPECT_EQ(Expression::Parse("exp(-200*u)").Evaluate(data),
            Eigen::Vector2d(std::exp(-600.0), std::exp(50.0)));
}

// Column-wise evaluation over several blocks agrees bit for bit with per-sample evaluation, and
// rows where an input channel is not sampled are NaN.
TEST_F(ExpressionTest, DatasetEvaluationMatchesPerSample) {
  const Eigen::Index n = 1000;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  Dataset data(Eigen::VectorXd::LinSpaced(n, 0.0, 99.9));
  for (const char* name : {"u", "v", "r", "tau_x"}) {
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) x(i) = noise(rng);
    data.Set(name, x);
  }
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled = Eigen::Array<bool, Eigen::Dynamic, 1>::Ones(n);
  sampled(10) = sampled(700) = false;
  data.Set("tau_x", data["tau_x"], sampled);
  data.Set("unused", Eigen::VectorXd::Zero(n));
  const Expression e = Expression::Parse(
      "v*r - 0.0101*u - 0.0492*abs(u)*u + 0.2*tau_x + tanh(u*v)/r - sqrt(v)*exp(-u*u)"
      " + sin(r)*cos(v)");
  const Eigen::VectorXd all = e.Evaluate(data);
  ASSERT_EQ(all.size(), n);
  for (Eigen::Index i = 0; i < n; ++i) {
    std::vector<double> x;
    for (const std::string& name : e.Variables()) x.push_back(data[name](i));
    if (!sampled(i)) {
      EXPECT_TRUE(std::isnan(all(i))) << i;
    } else {
      EXPECT_TRUE(Same(all(i), e.Evaluate(x))) << i;
    }
  }
}

// The columns of a simulation's batch (GP's segment simulator computes its regime features so):
// any number of rows, across the block size and below it, bit for bit as per sample.
TEST_F(ExpressionTest, ColumnEvaluationMatchesPerSample) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Expression e = Expression::Parse("abs(sqrt(u*u + v*v)/3.1 - 0.4) - 1/v + exp(u)*2");
  for (const Eigen::Index rows :
       {Eigen::Index{1}, Eigen::Index{7}, Eigen::Index{256}, Eigen::Index{600}}) {
    std::vector<Eigen::VectorXd> columns(e.Variables().size(), Eigen::VectorXd(rows));
    for (Eigen::VectorXd& c : columns)
      for (Eigen::Index i = 0; i < rows; ++i) c(i) = noise(rng);
    columns[1](0) = 0.0;  // protected division
    std::vector<const double*> pointers;
    for (const Eigen::VectorXd& c : columns) pointers.push_back(c.data());
    Eigen::VectorXd out(rows);
    e.EvaluateColumns(pointers, rows, out.data());
    for (Eigen::Index i = 0; i < rows; ++i) {
      const std::vector<double> x = {columns[0](i), columns[1](i)};
      EXPECT_TRUE(Same(out(i), e.Evaluate(x))) << rows << " rows, row " << i;
    }
  }
}

// Evaluation folds a constant or a variable into the operator that takes it as its right operand
// (Expression::Fuse); each binary operator then computes exactly what the operator itself does,
// protected division by a near-zero operand included.
TEST_F(ExpressionTest, FoldedRightOperandsComputeTheOperatorExactly) {
  const std::pair<const char*, OpCode> ops[] = {{"+", OpCode::kAdd},
                                                {"-", OpCode::kSubtract},
                                                {"*", OpCode::kMultiply},
                                                {"/", OpCode::kDivide}};
  const double u = 0.731, r = -1.9, v = 1e-13;  // v: below the protected division's epsilon
  for (const auto& [symbol, op] : ops) {
    for (const std::string right : {"v", "r", "0.37", "1e-13"}) {
      const double rhs = right == "v" ? v : right == "r" ? r : std::stod(right);
      const Expression e = Expression::Parse("(u*u) " + std::string(symbol) + " " + right);
      std::vector<double> x;
      for (const std::string& name : e.Variables())
        x.push_back(name == "u" ? u : name == "r" ? r : v);
      EXPECT_TRUE(Same(e.Evaluate(x), ApplyOperator(op, u * u, rhs))) << symbol << right;
    }
  }
}

// A channel the data lack is named in the error, with the equation it is needed for.
TEST_F(ExpressionTest, DatasetEvaluationThrowsOnMissingChannel) {
  Dataset data(Eigen::Vector2d(0.0, 1.0));
  data.Set("u", Eigen::Vector2d(1.0, 2.0));
  const Expression e = Expression::Parse("u + tau_x", "model.json: equation for u");
  try {
    e.Evaluate(data);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), StartsWith("model.json: equation for u: "));
    EXPECT_THAT(error.what(), HasSubstr("'tau_x'"));
  }
}

// The surge equation splits into its four physical terms with their coefficients.
TEST_F(ExpressionTest, TermsOfOdinSurgeEquation) {
  EXPECT_EQ(TermsOf("v*r - 0.010132*u - 0.04924*abs(u)*u + 2.0263e-4*tau_x"),
            (Terms{{"r*v", 1.0}, {"u", -0.010132}, {"abs(u)*u", -0.04924}, {"tau_x", 2.0263e-4}}));
  EXPECT_EQ(
      TermsOf(kYaw),
      (Terms{{"v", -0.061210}, {"r", -0.061210}, {"abs(r)*r", -0.142154}, {"tau_n", 4.7783e-5}}));
}

// Products distribute over sums, and like terms merge.
TEST_F(ExpressionTest, TermsExpandProducts) {
  EXPECT_EQ(TermsOf("2*(u + v)*r"), (Terms{{"r*u", 2.0}, {"r*v", 2.0}}));
  EXPECT_EQ(TermsOf("(u - v)*(u + v)"), (Terms{{"u*u", 1.0}, {"v*v", -1.0}}));
  EXPECT_EQ(TermsOf("u*r + r*u + 3*u - u"), (Terms{{"r*u", 2.0}, {"u", 2.0}}));
  EXPECT_EQ(TermsOf("(u + 1)*(u + 1)*u"), (Terms{{"u*u*u", 1.0}, {"u*u", 2.0}, {"u", 1.0}}));
}

// Constants, division, abs and unexpandable functions take the documented normal form, and
// every term string parses.
TEST_F(ExpressionTest, TermsNormaliseFactors) {
  EXPECT_EQ(TermsOf("u - 3 + 1"), (Terms{{"u", 1.0}, {"1", -2.0}}));
  EXPECT_EQ(TermsOf("(u + v)/4"), (Terms{{"u", 0.25}, {"v", 0.25}}));
  EXPECT_EQ(TermsOf("u/0"), (Terms{{"u", 1.0}}));
  EXPECT_EQ(TermsOf("3*u/(2*v)"), (Terms{{"1/v*u", 1.5}}));
  EXPECT_EQ(TermsOf("u/(v*r)"), (Terms{{"1/r*1/v*u", 1.0}}));
  EXPECT_EQ(TermsOf("u/r/v"), (Terms{{"1/r*1/v*u", 1.0}}));
  EXPECT_EQ(TermsOf("u/(v + 1)"), (Terms{{"1/(1 + v)*u", 1.0}}));
  EXPECT_EQ(TermsOf("abs(-2*u)*u"), (Terms{{"abs(u)*u", 2.0}}));
  EXPECT_EQ(TermsOf("2*tanh(v + u)"), (Terms{{"tanh(u + v)", 2.0}}));
  EXPECT_EQ(TermsOf("tanh(2*u - v)*r"), (Terms{{"r*tanh(2*u - v)", 1.0}}));
  EXPECT_EQ(TermsOf("exp(u - u)*v"), (Terms{{"v", 1.0}}));
  EXPECT_TRUE(TermsOf("u*v - v*u").empty());
  for (const char* text : {"3*u/(2*v)", "u/(v + 1)", "tanh(2*u - v)*r/(v*r)", kSway}) {
    for (const auto& [term, c] : Expression::Parse(text).Terms()) {
      EXPECT_NO_THROW(Expression::Parse(term)) << term;
    }
  }
}

// EvaluateT on ceres::Jet carries exact derivatives: the surge equation's Jacobian by hand, and
// every operator against central differences.
TEST_F(ExpressionTest, EvaluateTGivesJetDerivatives) {
  using Jet = ceres::Jet<double, 4>;
  const Expression surge = Expression::Parse(kSurge);
  ASSERT_EQ(surge.Variables(), (std::vector<std::string>{"r", "tau_x", "u", "v"}));
  const double r = 0.1, tau_x = 1000, u = -2.0, v = 0.5;
  const Jet x[] = {Jet(r, 0), Jet(tau_x, 1), Jet(u, 2), Jet(v, 3)};
  const Jet y = surge.EvaluateT(x);
  EXPECT_NEAR(y.a, surge.Evaluate(std::vector<double>{r, tau_x, u, v}), 1e-15);
  EXPECT_NEAR(y.v[0], v, 1e-15);
  EXPECT_NEAR(y.v[1], 2.0263e-4, 1e-18);
  EXPECT_NEAR(y.v[2], -0.010132 - 2 * 0.04924 * std::abs(u), 1e-14);
  EXPECT_NEAR(y.v[3], r, 1e-15);

  const Expression e = Expression::Parse(
      "tanh(u*v)/(r + 2) - sqrt(v)*exp(-u*u) + sin(r)*cos(v) + abs(u)*tau_x - -u");
  std::vector<double> p = {0.3, 0.7, -0.4, 1.3};
  Jet jets[4];
  for (int i = 0; i < 4; ++i) jets[i] = Jet(p[i], i);
  const Jet f = e.EvaluateT(jets);
  EXPECT_EQ(f.a, e.Evaluate(p));
  const double h = 1e-6;
  for (int i = 0; i < 4; ++i) {
    std::vector<double> plus = p, minus = p;
    plus[i] += h;
    minus[i] -= h;
    EXPECT_NEAR(f.v[i], (e.Evaluate(plus) - e.Evaluate(minus)) / (2 * h), 1e-8) << i;
  }
}

// Evaluating one sample allocates nothing: the hot path of every free-run simulation.
TEST_F(ExpressionTest, EvaluateDoesNotAllocate) {
  const Expression e = Expression::Parse(kSurge);
  const std::vector<double> x = {0.1, 1000, 2.0, 0.5};
  double sum = 0.0;
  t_allocations = 0;
  t_counting = true;
  for (int i = 0; i < 1000; ++i) sum += e.Evaluate(x);
  t_counting = false;
  EXPECT_EQ(t_allocations, 0);
  EXPECT_NEAR(sum, 1000 * 0.035406, 1e-9);
}

}  // namespace
}  // namespace usvid
