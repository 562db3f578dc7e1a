#include "harness/cross_validation.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "core/error.h"

namespace usvid {

std::string FoldName(const std::string& run) { return "all but " + run; }

void ExpandCrossValidation(Suite& suite, const std::string& kind, const std::string& file) {
  const std::string where = file + ": cv";
  if (kind != kCrossValidationRuns)
    throw InputError(where + ": '" + kind + "' is unknown (known: " + kCrossValidationRuns +
                     ", leave one run out)");
  if (!suite.Measured())
    throw InputError(where +
                     ": a simulated suite has no runs to leave out (cv needs a suite "
                     "on measured data, \"data\": {...})");
  SuiteCrossValidation cv;
  cv.kind = kind;
  cv.given_train = suite.train_data;
  cv.given_test = suite.test_data;
  std::vector<SuiteData> runs;
  for (const SuiteData& d : cv.given_train)
    for (const std::string& f : d.files) {
      SuiteData run = d;
      run.files = {f};
      if (d.files.size() > 1) run.name += ": " + std::filesystem::path(f).stem().string();
      runs.push_back(run);
    }
  for (const SuiteData& d : cv.given_test) runs.push_back(d);
  if (runs.size() < 2)
    throw InputError(where + ": leaving one run out needs at least two runs; the suite has " +
                     std::to_string(runs.size()) + " ('" + runs.front().name + "')");
  std::map<std::string, size_t> names;
  std::map<std::tuple<std::string, double, double>, size_t> rows;
  for (size_t i = 0; i < runs.size(); ++i) {
    const SuiteData& r = runs[i];
    if (const auto [it, fresh] = names.emplace(r.name, i); !fresh)
      throw InputError(where + ": two runs are named '" + r.name + "'");
    const auto key = std::make_tuple(std::filesystem::path(r.files[0]).lexically_normal().string(),
                                     r.from_s, r.to_s);
    if (const auto [it, fresh] = rows.emplace(key, i); !fresh)
      throw InputError(where + ": '" + runs[it->second].name + "' and '" + r.name +
                       "' are the same rows of " + r.files[0] +
                       ": the run left out would still be trained on");
  }
  suite.test_data = runs;
  suite.test_maneuvers.clear();
  suite.train_maneuvers.clear();
  for (const SuiteData& r : runs) {
    suite.test_maneuvers.push_back(r.name);
    suite.train_maneuvers.push_back(FoldName(r.name));
    cv.held_out[FoldName(r.name)] = r.name;
  }
  suite.cv = std::move(cv);
}

std::vector<std::string> ScoredTests(const Suite& suite, const std::string& train) {
  if (!suite.cv.On()) return suite.test_maneuvers;
  return {suite.cv.held_out.at(train)};
}

std::vector<std::string> FoldTrainingRuns(const Suite& suite, const std::string& train) {
  const std::string& left_out = suite.cv.held_out.at(train);
  std::vector<std::string> runs;
  for (const std::string& run : suite.test_maneuvers)
    if (run != left_out) runs.push_back(run);
  return runs;
}

std::string TrainingLabel(const Suite& suite, const std::string& train) {
  return suite.cv.On() ? std::string(kLeaveOneRunOut) : train;
}

std::vector<std::string> TrainingLabels(const Suite& suite) {
  if (suite.cv.On()) return {kLeaveOneRunOut};
  return suite.train_maneuvers;
}

}  // namespace usvid
