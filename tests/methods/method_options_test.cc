// A method's options, declared once (methods/method_options.h): what the command line, suites
// and Python all check through, and every registered method's declaration itself.
#include "methods/method_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <stdexcept>

#include "core/error.h"
#include "methods/registry.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

const std::vector<OptionSpec>& Specs() {
  static const std::vector<OptionSpec> specs = [] {
    std::vector<OptionSpec> s = {
        IntegerOption("population", 2000, 4, 1e6, "trees"),
        NumberOption("horizon_s", std::nullopt, 0, 600, "seconds", /*min_exclusive=*/true),
        ChoiceOption("fit", "simulation", {"simulation", "equation"}, "how"),
        ListOption("library", {"constant", "abs"}, {"constant", "products", "abs"}, "terms"),
        FlagOption("robust", "Huber"),
    };
    s[1].old_keys = {"horizon"};
    return s;
  }();
  return specs;
}

std::string Refusal(const nlohmann::json& given) {
  try {
    ValidateOptions("toy", Specs(), given, "suite.json: methods");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(MethodOptionsTest, DefaultsFillWhatIsNotGivenAndGivenIsKnown) {
  const MethodOptions o = ValidateOptions("toy", Specs(), {{"fit", "equation"}}, "");
  EXPECT_EQ(o.Integer("population"), 2000);
  EXPECT_FALSE(o.Given("population"));
  EXPECT_TRUE(o.Given("fit"));
  EXPECT_EQ(o.Text("fit"), "equation");
  EXPECT_FALSE(o.Has("horizon_s"));  // no default: the method decides
  EXPECT_EQ(o.OptionalNumber("horizon_s"), std::nullopt);
  EXPECT_EQ(o.List("library"), (std::vector<std::string>{"constant", "abs"}));
  EXPECT_FALSE(o.Flag("robust"));
  EXPECT_EQ(o.Json()["population"], 2000);
  EXPECT_FALSE(o.Json().contains("horizon_s"));
}

// The contract of every refusal: one line with where, the method, the key and what is allowed.
TEST(MethodOptionsTest, RefusalsNameTheMethodTheKeyAndWhatIsAllowed) {
  EXPECT_EQ(Refusal({{"causes", 3}}),
            "suite.json: methods: method toy: unknown option 'causes' (its options: population, "
            "horizon_s, fit, library, robust)");
  EXPECT_EQ(Refusal({{"population", 3}}),
            "suite.json: methods: method toy: option 'population' 3 is not allowed: a whole "
            "number in [4, 1000000]");
  EXPECT_THAT(Refusal({{"population", 50.5}}), HasSubstr("option 'population' 50.5"));
  EXPECT_THAT(Refusal({{"population", "50"}}), HasSubstr("a whole number in [4, 1000000]"));
  EXPECT_THAT(Refusal({{"population", 1e300}}), HasSubstr("option 'population'"));
  EXPECT_THAT(Refusal({{"horizon_s", 0}}), HasSubstr("a finite number in (0, 600]"));
  EXPECT_THAT(Refusal({{"fit", "shooting"}}), HasSubstr("one of simulation, equation"));
  EXPECT_THAT(Refusal({{"library", {"constant", "cubic"}}}),
              HasSubstr("a list of constant, products, abs"));
  EXPECT_THAT(Refusal({{"library", {"constant", 3}}}), HasSubstr("option 'library'"));
  EXPECT_THAT(Refusal({{"robust", 1}}), HasSubstr("true or false"));
  EXPECT_THAT(Refusal(nlohmann::json::array()), HasSubstr("method toy: options must be"));
  EXPECT_EQ(Refusal(nlohmann::json()), "accepted");  // none given
}

TEST(MethodOptionsTest, ListsReadFromCommasAndOldKeysWithANote) {
  std::vector<std::string> notes;
  const MethodOptions o = ValidateOptions(
      "toy", Specs(), {{"library", "products,abs"}, {"horizon", 30}}, "s.json", &notes);
  EXPECT_EQ(o.List("library"), (std::vector<std::string>{"products", "abs"}));
  EXPECT_EQ(o.Number("horizon_s"), 30.0);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("option 'horizon' is now 'horizon_s'"));
  EXPECT_THAT(Refusal({{"horizon", 30}, {"horizon_s", 20}}), HasSubstr("given twice"));
}

TEST(MethodOptionsTest, CommandLineTextIsReadAsTheOptionsType) {
  const std::vector<OptionSpec>& s = Specs();
  EXPECT_EQ(OptionFromText("toy", s[0], "300"), nlohmann::json(300));
  EXPECT_EQ(OptionFromText("toy", s[1], "2.5"), nlohmann::json(2.5));
  EXPECT_EQ(OptionFromText("toy", s[3], "constant,abs"), nlohmann::json({"constant", "abs"}));
  EXPECT_EQ(OptionFromText("toy", s[4], "true"), nlohmann::json(true));
  try {
    OptionFromText("toy", s[0], "3e2.5");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "--population '3e2.5': method toy: allowed: a whole number in [4, 1000000]");
  }
  EXPECT_THROW(OptionFromText("toy", s[0], "12.5"), InputError);
  EXPECT_THROW(OptionFromText("toy", s[1], "nan"), InputError);
}

TEST(MethodOptionsTest, ReadsAreCountedAndAnUndeclaredReadIsAProgrammingError) {
  const MethodOptions o = ValidateOptions("toy", Specs(), nlohmann::json::object(), "");
  EXPECT_EQ(o.Unread().size(), Specs().size());
  o.Integer("population");
  o.Has("horizon_s");
  EXPECT_EQ(o.Unread(), (std::vector<std::string>{"fit", "library", "robust"}));
  EXPECT_THROW(o.Number("ridge"), std::logic_error);
}

// Every registered method's declaration: keys in snake_case, each once, with one line of help,
// and a default that its own check accepts (so that an unset option never fails a fit).
TEST(MethodOptionsTest, EveryMethodsDeclarationIsWellFormed) {
  const std::regex snake("[a-z][a-z0-9]*(_[a-z0-9]+)*");
  for (const Method& m : Methods()) {
    std::set<std::string> keys;
    for (const OptionSpec& s : m.options) {
      SCOPED_TRACE(m.name + "." + s.key);
      EXPECT_TRUE(std::regex_match(s.key, snake));
      EXPECT_TRUE(keys.insert(s.key).second) << "declared twice";
      EXPECT_FALSE(s.help.empty());
      EXPECT_EQ(s.help.find('\n'), std::string::npos);
      if (!s.default_value.is_null()) {
        EXPECT_NO_THROW(ValidateOptions(m.name, m.options, {{s.key, s.default_value}}, ""));
      }
      if (s.type == OptionType::kChoice) {
        EXPECT_FALSE(s.choices.empty());
      }
    }
  }
}

}  // namespace
}  // namespace usvid
