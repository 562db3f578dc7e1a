// A log with a text column (issue 25; docs/data.md#text-columns): every command that does not
// use the column reads the log as if the column were not there, with one note on stderr; a
// command that needs it as a number refuses it with exit 2, naming file:line:column.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;

// Appends a column `mode` (text: "auto", "manual") to every row of a data CSV.
void AddModeColumn(const fs::path& from, const fs::path& to) {
  std::ifstream in(from);
  std::ofstream out(to);
  std::string line;
  bool header = true;
  int row = 0;
  while (std::getline(in, line)) {
    out << line << ',' << (header ? "mode" : (row++ / 50) % 2 ? "manual" : "auto") << '\n';
    header = false;
  }
}

int Lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

class TextColumnCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    const auto sim = RunUsvid(
        "simulate --vessel odin3dof --maneuver zigzag:20/20 --duration 60 "
        "--out " +
        (dir_ / "plain.csv").string());
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    AddModeColumn(dir_ / "plain.csv", dir_ / "log.csv");
    log_ = (dir_ / "log.csv").string();
  }
  fs::path dir_;
  std::string log_;
};

// info, identify, evaluate, preprocess, simulate --inputs and diagnose accept the log, each with
// one note naming the column, and give what they give on the log without it.
TEST_F(TextColumnCliTest, CommandsThatDoNotUseItAcceptTheLogWithOneNote) {
  const std::string model = (dir_ / "model.json").string();
  const std::string commands[] = {
      "info --data " + log_,
      "identify --method sindy --vessel odin3dof --data " + log_ + " --out " + model,
      "evaluate --model " + model + " --data " + log_ + " --out " + (dir_ / "eval").string(),
      "preprocess --data " + log_ + " --states u v r --inputs tau_x tau_y tau_n --out " +
          (dir_ / "pre.csv").string(),
      "simulate --vessel odin3dof --inputs " + log_ + " --out " + (dir_ / "replay.csv").string(),
      "diagnose --vessel odin3dof --causes 1 --data " + log_ + " --out " + (dir_ / "diag").string(),
  };
  for (const std::string& args : commands) {
    SCOPED_TRACE(args);
    const auto r = RunUsvid(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream err(r.err);
    int notes = 0;
    for (std::string line; std::getline(err, line);)
      if (line.find("note: column 'mode' is text ('auto' at " + log_ + ":2:") != std::string::npos)
        ++notes;
    EXPECT_EQ(notes, 1) << r.err;
  }
  // The text column changes nothing in what is fitted.
  const auto plain =
      RunUsvid("identify --method sindy --vessel odin3dof --data " + (dir_ / "plain.csv").string() +
               " --out " + (dir_ / "plain_model.json").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto equations = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    return text.substr(text.find("\"equations\""),
                       text.find("\"inputs\"") - text.find("\"equations\""));
  };
  EXPECT_EQ(equations(dir_ / "model.json"), equations(dir_ / "plain_model.json"));
}

// Asked for as a number, the column is refused where its text first stood.
TEST_F(TextColumnCliTest, ACommandThatNeedsItAsANumberIsRefusedAtItsFirstText) {
  const std::string out = (dir_ / "m.json").string();
  const auto r = RunUsvid("identify --method sindy --data " + log_ +
                          " --states u --inputs tau_x mode --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(log_ + ":2:"));
  EXPECT_THAT(r.err, HasSubstr("column 'mode': 'auto' is not a number"));
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(Lines(r.err), 2) << r.err;  // the note, then the error
}

}  // namespace
}  // namespace usvid
