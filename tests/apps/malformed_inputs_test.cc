// The catalogue of malformed inputs (issue 11): each is refused as docs/data.md#command-line
// says: exit code 2, one line on stderr naming the file (and line and column where there is
// one) or the option at fault, no output file left behind, no crash. One test per input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;

struct Malformed {
  const char* name;
  const char* args;  // {D} is the test's folder, {OUT} the output that must not appear
  const char* says;  // expected on stderr
};

// A folder removed when the process ends.
struct OwnedFolder {
  fs::path path;
  ~OwnedFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// The inputs every case may use, made once per process in a folder of their own.
const fs::path& Inputs() {
  static const OwnedFolder dir{[] {
    // One folder per process: ctest runs the cases as separate processes, in parallel.
    const fs::path d =
        fs::temp_directory_path() / ("usvid_malformed_inputs_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    const auto sim = RunUsvid(
        "simulate --vessel odin3dof --maneuver zigzag:20/20 --duration 30 "
        "--out " +
        (d / "good.csv").string());
    EXPECT_EQ(sim.exit_code, 0) << sim.err;
    const auto id = RunUsvid("identify --method sindy --vessel odin3dof --data " +
                             (d / "good.csv").string() + " --out " + (d / "model.json").string());
    EXPECT_EQ(id.exit_code, 0) << id.err;
    WriteText(d / "truncated.json", R"({"method": "gp", "equations": {"u": "u)");
    WriteText(d / "model_types.json", R"({"method": "gp", "equations": {"u": 3}})");
    WriteText(d / "model_syntax.json", R"({"method": "gp", "equations": {"u": "2*(u + "}})");
    WriteText(d / "model_channel.json", R"({"method": "gp", "equations": {"u": "warp*u"}})");
    WriteText(d / "model_array.json", R"([1, 2, 3])");
    WriteText(d / "model_vessel.json", R"({"vessel": "titanic"})");
    WriteText(d / "suite_unknown.json", R"({"vessels": ["odin3dof"], "train_maneuvers": ["prbs"],
      "test_maneuvers": ["prbs"], "methods": ["sindy"], "colour": "blue"})");
    WriteText(d / "suite_types.json", R"({"vessels": "odin3dof", "train_maneuvers": ["prbs"],
      "test_maneuvers": ["prbs"], "methods": ["sindy"]})");
    WriteText(d / "suite_truncated.json", R"({"vessels": ["odin3dof"], "train_man)");
    WriteText(d / "params_unknown.json", R"({"warp_factor": 9})");
    WriteText(d / "params_types.json", R"({"m11": "heavy"})");
    WriteText(d / "no_time.csv", "time,u\n0,1\n1,2\n");
    WriteText(d / "text.csv", "t,u\n0,1\n1,fast\n");
    WriteText(d / "backwards.csv", "t,u\n0,1\n2,2\n1,3\n");
    WriteText(d / "short_row.csv", "t,u,v\n0,1,2\n1,2\n");
    WriteText(d / "inf.csv", "t,u\n0,1\n1,inf\n");
    WriteText(d / "no_inputs.csv", "t,u,v,r\n0,1,0,0\n1,1,0,0\n");
    WriteText(d / "empty.csv", "");
    fs::create_directories(d / "a_folder");
    return d;
  }()};
  return dir.path;
}

std::string Expand(std::string text, const fs::path& out) {
  for (const auto& [key, value] :
       {std::pair{std::string("{D}"), Inputs().string()}, {std::string("{OUT}"), out.string()}}) {
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key))
      text.replace(at, key.size(), value);
  }
  return text;
}

class MalformedInputTest : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedInputTest, ExitsTwoNamesTheCulpritAndWritesNothing) {
  const Malformed& m = GetParam();
  const fs::path out = fs::temp_directory_path() / (std::string("usvid_malformed_out_") + m.name);
  fs::remove_all(out);
  fs::remove_all(out.string() + ".csv");
  fs::remove_all(out.string() + ".json");
  const auto r = RunUsvid(Expand(m.args, out));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(Expand(m.says, out)));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
  EXPECT_FALSE(fs::exists(out / "metrics.json") || fs::exists(out / "results.json") ||
               fs::exists(out / "diagnosis.json") || fs::exists(out.string() + ".csv") ||
               fs::exists(out.string() + ".json"));
}

const Malformed kCatalogue[] = {
    // Data CSV (docs/data.md#data-files).
    {"csv_no_time", "info --data {D}/no_time.csv", "no_time.csv"},
    {"csv_text_cell", "info --data {D}/text.csv", "text.csv:3:3"},
    {"csv_backwards_time", "info --data {D}/backwards.csv", "backwards.csv:4"},
    {"csv_short_row", "info --data {D}/short_row.csv", "short_row.csv:3"},
    {"csv_inf", "info --data {D}/inf.csv", "inf.csv:3:3"},
    {"csv_empty", "info --data {D}/empty.csv", "empty.csv"},
    {"csv_missing_file", "info --data {D}/nothing_here.csv", "nothing_here.csv"},
    {"csv_is_a_folder", "info --data {D}/a_folder", "a_folder"},
    {"csv_without_inputs", "simulate --vessel odin3dof --inputs {D}/no_inputs.csv --out {OUT}.csv",
     "tau_x"},
    // Model JSON.
    {"model_truncated", "evaluate --model {D}/truncated.json --data {D}/good.csv",
     "truncated.json:1"},
    {"model_wrong_type", "evaluate --model {D}/model_types.json --data {D}/good.csv",
     "not a string"},
    {"model_syntax", "evaluate --model {D}/model_syntax.json --data {D}/good.csv", "column"},
    {"model_unknown_channel", "evaluate --model {D}/model_channel.json --data {D}/good.csv",
     "warp"},
    {"model_not_an_object", "evaluate --model {D}/model_array.json --data {D}/good.csv",
     "model_array.json"},
    {"model_unknown_vessel", "evaluate --model {D}/model_vessel.json --data {D}/good.csv",
     "titanic"},
    {"model_missing", "evaluate --model {D}/none.json --data {D}/good.csv", "none.json"},
    // Several records to score: a bad one leaves no output, and a maneuver is one record's.
    {"evaluate_bad_record_in_list",
     "evaluate --model {D}/model.json --data {D}/good.csv,{D}/text.csv --out {OUT}",
     "text.csv:3:3"},
    {"evaluate_maneuver_of_several_records",
     "evaluate --model {D}/model.json --data {D}/good.csv,{D}/good.csv --maneuver zigzag:20/20 "
     "--out {OUT}",
     "--maneuver names the maneuver of one record"},
    // A replay that would turn the other way from the record's test: the mirror image meets the
    // wind and the asymmetries from the other side (good.csv turns to starboard first).
    {"evaluate_maneuver_turning_the_other_way",
     "evaluate --model {D}/model.json --data {D}/good.csv --maneuver zigzag:-20/20 --out {OUT}",
     "zigzag:-20/20 turns to port first, the record to starboard (its execute at 5.0 s): give "
     "zigzag:20/20"},
    // A maneuver whose number does not parse, refused before the replay ("2x" is not 2).
    {"evaluate_maneuver_bad_number",
     "evaluate --model {D}/model.json --data {D}/good.csv --maneuver zigzag:2x/20 --out {OUT}",
     "--maneuver 'zigzag:2x/20': '2x' is not a number"},
    // Suite JSON.
    {"suite_unknown_field", "compare --suite {D}/suite_unknown.json --out {OUT}", "colour"},
    {"suite_wrong_type", "compare --suite {D}/suite_types.json --out {OUT}", "vessels"},
    {"suite_truncated", "compare --suite {D}/suite_truncated.json --out {OUT}",
     "suite_truncated.json:1"},
    // A bad baseline is refused before the fits, not after them.
    {"baseline_truncated", "compare --quick --baseline {D}/suite_truncated.json --out {OUT}",
     "suite_truncated.json:1"},
    // Parameter files.
    {"params_unknown",
     "simulate --vessel odin3dof --maneuver zigzag --params {D}/params_unknown.json "
     "--out {OUT}.csv",
     "warp_factor"},
    {"params_wrong_type",
     "simulate --vessel odin3dof --maneuver zigzag --params "
     "{D}/params_types.json --out {OUT}.csv",
     "m11"},
    // Command-line options.
    {"unknown_vessel", "simulate --vessel titanic --maneuver zigzag --out {OUT}.csv", "titanic"},
    {"unknown_method",
     "identify --method magic --vessel odin3dof --data {D}/good.csv --out "
     "{OUT}.json",
     "--method"},
    {"unknown_maneuver", "simulate --vessel odin3dof --maneuver loop --out {OUT}.csv", "loop"},
    {"unknown_effect",
     "simulate --vessel odin3dof --maneuver zigzag --effect gremlin=1 --out "
     "{OUT}.csv",
     "gremlin"},
    {"effect_not_a_number",
     "simulate --vessel odin3dof --maneuver zigzag --effect current=abc "
     "--out {OUT}.csv",
     "current=abc"},
    {"negative_duration",
     "simulate --vessel odin3dof --maneuver zigzag --duration -5 --out "
     "{OUT}.csv",
     "--duration"},
    {"negative_step", "simulate --vessel odin3dof --maneuver zigzag --dt -0.01 --out {OUT}.csv",
     "--dt"},
    {"zero_rate", "simulate --vessel odin3dof --maneuver zigzag --rate 0 --out {OUT}.csv",
     "--rate"},
    {"unwritable_output",
     "simulate --vessel odin3dof --maneuver zigzag --out "
     "/proc/usvid/x.csv",
     "/proc/usvid"},
    {"output_is_a_folder", "simulate --vessel odin3dof --maneuver zigzag --out {D}/a_folder",
     "a_folder"},
    {"diagnose_negative_fit_rows",
     "diagnose --data {D}/good.csv --vessel odin3dof --fit-rows -1 --out {OUT}", "--fit-rows"},
    {"fossen_negative_fit_rows",
     "identify --method fossen-ceres --data {D}/good.csv --vessel odin3dof --fit-rows -1 --out "
     "{OUT}.json",
     "--fit-rows"},
    // Several records (issue 38): an empty list or name, a record without a named channel.
    {"identify_empty_data_list",
     "identify --method sindy --vessel odin3dof --data '' --out {OUT}.json",
     "--data: an empty file name"},
    {"identify_record_without_channel",
     "identify --method sindy --states u,v,r --inputs tau_x --data {D}/good.csv,{D}/no_inputs.csv "
     "--out {OUT}.json",
     "no_inputs.csv: no channel 'tau_x' (every record of --data needs it)"},
    {"negative_threads", "diagnose --data {D}/good.csv --vessel odin3dof --threads -1 --out {OUT}",
     "--threads"},
    {"unknown_option", "info --data {D}/good.csv --colour blue", "--colour"},
};

INSTANTIATE_TEST_SUITE_P(Catalogue, MalformedInputTest, ::testing::ValuesIn(kCatalogue),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace usvid
