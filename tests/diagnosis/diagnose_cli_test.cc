// `usvid diagnose` as a user runs it (docs/data.md#diagnosisjson): diagnosis.json with its
// fields and no NaN, the extended model.json, a report.html with its figure inline; the same
// numbers at 1 and 2 threads; bad input is exit code 2 with a message naming what is wrong, and
// leaves no diagnosis.json behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "effects/effect.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

class DiagnoseCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    data_ = (dir_ / "data.csv").string();
    const auto r = RunUsvid(
        "simulate --vessel odin3dof --maneuver random-steps --duration 150 "
        "--noise 0.005 --seed 7 --effect input_delay=0.6 --out " +
        data_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  nlohmann::json Strip(nlohmann::json j) {
    if (j.is_object()) {
      j.erase("seconds");
      for (auto& [k, v] : j.items()) v = Strip(v);
    } else if (j.is_array()) {
      for (auto& v : j) v = Strip(v);
    }
    return j;
  }
  fs::path dir_;
  std::string data_;
};

TEST_F(DiagnoseCliTest, WritesTheContractFieldsModelAndReport) {
  const auto out = dir_ / "out";
  const auto r = RunUsvid("diagnose --vessel odin3dof --data " + data_ + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json d = ReadJsonFile((out / "diagnosis.json").string());
  EXPECT_EQ(d.at("vessel"), "odin3dof");
  EXPECT_EQ(d.at("cause"), "input_delay");
  for (const char* c : {"u", "v", "r"}) EXPECT_TRUE(d.at("nominal").at("fit_percent").contains(c));
  for (const char* c : {"u", "v", "r"}) EXPECT_TRUE(d.at("residuals").contains(c));
  // Every effect but wind (odin3dof has no wind model) is tried on the whole vessel, and those
  // that can act on one input on each of odin3dof's three inputs (input_bias on the two that
  // are not the yaw input): 10 + 11.
  size_t whole = 0, one_input = 0;
  for (const auto& c : d.at("candidates")) {
    if (!c.contains("inputs")) {
      ++whole;
      continue;
    }
    ++one_input;
    EXPECT_TRUE(OnInputs(EffectFromJson(c).kind)) << c.dump();
    EXPECT_EQ(c.at("inputs").size(), 1u);
  }
  EXPECT_EQ(whole, EffectCatalogue().size() - 1);
  EXPECT_EQ(one_input, 11u);
  double last_score = -1e300;
  for (const auto& c : d.at("candidates")) {
    for (const char* f : {"effect", "parameters", "heldout_fit_percent", "score"})
      EXPECT_TRUE(c.contains(f)) << f;
    EXPECT_GE(c.at("score").get<double>(), last_score) << "ranked best first";
    last_score = c.at("score").get<double>();
  }
  EXPECT_TRUE(d.at("extended").at("heldout_fit_percent").contains("r"));
  EXPECT_GT(d.at("gain").at("heldout_error_reduction").get<double>(), 0.5);
  EXPECT_EQ(d.dump().find("null"), std::string::npos);
  const nlohmann::json model = ReadJsonFile((out / "model.json").string());
  EXPECT_EQ(model.at("effects").at(0).at("effect"), "input_delay");
  const std::string html = ReadTextFile((out / "report.html").string());
  EXPECT_THAT(html, HasSubstr("<svg"));
  EXPECT_THAT(html, HasSubstr("Cause: input_delay"));
  EXPECT_TRUE(fs::exists(out / "heldout.svg"));
}

TEST_F(DiagnoseCliTest, SameNumbersAtOneAndTwoThreads) {
  const auto one = RunUsvid("diagnose --threads 1 --vessel odin3dof --data " + data_ + " --out " +
                            (dir_ / "one").string());
  const auto two = RunUsvid("diagnose --threads 2 --vessel odin3dof --data " + data_ + " --out " +
                            (dir_ / "two").string());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(Strip(ReadJsonFile((dir_ / "one" / "diagnosis.json").string())),
            Strip(ReadJsonFile((dir_ / "two" / "diagnosis.json").string())));
}

TEST_F(DiagnoseCliTest, BadInputIsExitTwoWithAMessageAndNoOutput) {
  const std::string no_yaw = (dir_ / "no_yaw.csv").string();
  WriteText(no_yaw, "t,u,v,r,tau_x,tau_y\n0,1,0,0,1,0\n0.05,1,0,0,1,0\n");
  const std::string short_data = (dir_ / "short.csv").string();
  WriteText(short_data, "t,u,v,r,tau_x,tau_y,tau_n\n0,1,0,0,1,0,0\n0.05,1,0,0.01,1,0,0\n");
  const std::string params = (dir_ / "params.json").string();
  WriteText(params, R"({"m11": 5000, "wings": 2})");
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--vessel odin3dof --data " + no_yaw, "no_yaw.csv: no input column 'tau_n'"},
      {"--vessel odin3dof --data " + short_data, "short.csv: too few rows"},
      {"--vessel submarine --data " + data_, "--vessel 'submarine': unknown vessel"},
      {"--vessel odin3dof --data " + (dir_ / "missing.csv").string(), "missing.csv"},
      {"--vessel odin3dof --data " + data_ + " --params " + params, "no parameter 'wings'"},
      {"--vessel odin3dof --data " + data_ + " --segment -1", "--segment must be positive"},
      {"--vessel odin3dof --data " + data_ + " --heldout 1.5", "--heldout"},
  };
  for (const Case& c : cases) {
    const auto out = dir_ / "bad";
    const auto r = RunUsvid("diagnose " + c.args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message)) << c.args;
    EXPECT_FALSE(fs::exists(out / "diagnosis.json")) << c.args;
  }
}

}  // namespace
}  // namespace usvid
