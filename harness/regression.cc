#include "harness/regression.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "core/nan.h"
#include "metrics/rank_tests.h"

namespace usvid {
namespace {

constexpr double kMinShiftPoints = 0.5;  // a fit difference smaller than this is no change
constexpr double kAlpha = 0.05;          // family-wise, by Holm
constexpr int kMinNonzeroPairs = 6;      // below, no two-sided signed-rank p reaches kAlpha
constexpr double kSlowerRatio = 1.5;     // median fit time grew by more than 50 %
constexpr double kWorst = -std::numeric_limits<double>::infinity();

// vessel, train_maneuver, test_maneuver, method, noise, seed.
using PairKey = std::tuple<std::string, std::string, std::string, std::string, double, uint64_t>;
using GroupKey = std::pair<std::string, std::string>;      // vessel, method
using FitKey = std::tuple<std::string, double, uint64_t>;  // train_maneuver, noise, seed

struct Cell {
  std::string status;
  double fit = 0.0;
  double seconds = 0.0;
};

struct Group {
  std::vector<double> fit_now, fit_before;                 // paired "ok" cells
  std::map<FitKey, std::pair<double, double>> seconds;     // per fit: now, baseline
  nlohmann::json newly_failing = nlohmann::json::array();  // the cells
  int newly_ok = 0, failing_both = 0, only_now = 0, only_baseline = 0;
  int cells_now = 0, cells_before = 0;
};

double FitOrWorst(double fit) { return std::isnan(fit) ? kWorst : fit; }

// A number for the JSON, null when it is not finite (nlohmann writes those as null anyway).
nlohmann::json JsonNumber(double x) { return std::isfinite(x) ? nlohmann::json(x) : nullptr; }

// Row `index` of the baseline, its fields checked by name.
class BaselineRow {
 public:
  BaselineRow(const nlohmann::json& row, size_t index, const std::string& file)
      : row_(row), where_(file + ": rows[" + std::to_string(index) + "]") {
    if (!row.is_object()) throw InputError(where_ + " is not an object");
  }
  template <typename T>
  T Get(const char* field) const {
    try {
      return At(field).get<T>();
    } catch (const nlohmann::json::exception&) {
      throw InputError(where_ + ": field \"" + field + "\" has the wrong type (" +
                       At(field).dump() + ")");
    }
  }
  double Fit() const {
    return At("mean_fit_percent").is_null() ? kWorst : FitOrWorst(Get<double>("mean_fit_percent"));
  }

 private:
  const nlohmann::json& At(const char* field) const {
    const auto it = row_.find(field);
    if (it == row_.end()) throw InputError(where_ + ": no field \"" + field + "\"");
    return *it;
  }
  const nlohmann::json& row_;
  std::string where_;
};

void AddPair(const PairKey& key, const Cell& now, const Cell& before, Group* g) {
  const auto& [vessel, train, test, method, noise, seed] = key;
  const bool ok_now = now.status == "ok", ok_before = before.status == "ok";
  if (ok_now && ok_before) {
    g->fit_now.push_back(now.fit);
    g->fit_before.push_back(before.fit);
    g->seconds.try_emplace({train, noise, seed}, now.seconds, before.seconds);
  } else if (ok_before) {
    g->newly_failing.push_back({{"train_maneuver", train},
                                {"test_maneuver", test},
                                {"noise", noise},
                                {"seed", seed},
                                {"status", now.status}});
  } else if (ok_now) {
    ++g->newly_ok;
  } else {
    ++g->failing_both;
  }
}

struct Paired {
  int pairs = 0;
  double median_now = kNaN, median_before = kNaN;
  Spread difference;
  SignedRankTest test;
};

Paired ComparePairs(const std::vector<double>& now, const std::vector<double>& before) {
  Paired p;
  p.pairs = static_cast<int>(now.size());
  std::vector<double> d(now.size());
  for (size_t i = 0; i < now.size(); ++i) d[i] = now[i] == before[i] ? 0.0 : now[i] - before[i];
  p.median_now = Median(now);
  p.median_before = Median(before);
  p.difference = Describe(d);
  p.test = WilcoxonSignedRank(now, before);
  return p;
}

std::string Verdict(const Group& g, const Paired& fit, double fit_p_adjusted, const Paired& time,
                    double time_p_adjusted) {
  const bool fit_tested = fit.test.n >= kMinNonzeroPairs && fit_p_adjusted < kAlpha;
  if (!g.newly_failing.empty() || (fit_tested && fit.difference.median < -kMinShiftPoints))
    return "worse fit";
  if (time.test.n >= kMinNonzeroPairs && time_p_adjusted < kAlpha &&
      time.median_now > kSlowerRatio * time.median_before && time.difference.median > 0.0)
    return "slower";
  if (fit.pairs == 0 && g.cells_before == 0) return "not in the baseline";
  if (fit.pairs == 0 && g.cells_now == 0) return "not in this run";
  if (fit.pairs == 0 && g.newly_ok == 0 && g.failing_both > 0) return "same";  // fails as before
  if (fit.pairs == 0 || (fit.test.n > 0 && fit.test.n < kMinNonzeroPairs))
    return "too few pairs to test";
  if (fit_tested && fit.difference.median > kMinShiftPoints) return "better fit";
  return "same";
}

// Worst first: worse fit, slower, untested, better fit; within one, by median difference.
int Severity(const std::string& verdict) {
  if (verdict == "worse fit") return 0;
  if (verdict == "slower") return 1;
  if (verdict == "too few pairs to test") return 2;
  if (verdict == "better fit") return 4;
  return 3;  // not in the baseline / this run
}

std::string Format(const nlohmann::json& x, int decimals) {
  if (!x.is_number()) return "–";
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << x.get<double>();
  return s.str();
}

std::string FormatP(const nlohmann::json& x) {
  if (!x.is_number()) return "–";
  std::ostringstream s;
  s << std::setprecision(2) << x.get<double>();
  return s.str();
}

std::string OneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '|', '/');
  return s;
}

}  // namespace

std::string RegressionReport::Markdown() const {
  std::vector<const nlohmann::json*> shown;
  for (const auto& g : groups)
    if (g.at("verdict") != "same") shown.push_back(&g);
  std::stable_sort(shown.begin(), shown.end(),
                   [](const nlohmann::json* a, const nlohmann::json* b) {
                     const int sa = Severity(a->at("verdict")), sb = Severity(b->at("verdict"));
                     if (sa != sb) return sa < sb;
                     const auto diff = [](const nlohmann::json* g) {
                       const auto& d = g->at("median_difference");
                       return d.is_number() ? d.get<double>() : 0.0;
                     };
                     return sa == 4 ? diff(a) > diff(b) : diff(a) < diff(b);
                   });
  std::ostringstream md;
  md << "## Against the baseline\n\n"
     << worse << " of " << groups.size() << " groups (vessel, method) got worse.\n\n";
  if (shown.empty()) {
    md << "Every group is the same as in the baseline.\n\n";
  } else {
    md << "| vessel | method | pairs | median fit % | baseline | median difference | p (Holm) "
          "| verdict |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |\n";
    for (const nlohmann::json* g : shown) {
      std::string verdict = g->at("verdict");
      const int failing = g->at("newly_failing");
      if (failing > 0)
        verdict +=
            " (newly failing: " + std::to_string(failing) + (failing == 1 ? " cell)" : " cells)");
      const int fitting = g->at("newly_ok");
      if (fitting > 0)
        verdict +=
            " (newly fitting: " + std::to_string(fitting) + (fitting == 1 ? " cell)" : " cells)");
      if (verdict == "slower")
        verdict += " (median fit " + Format(g->at("fit_seconds").at("median"), 2) + " s, was " +
                   Format(g->at("fit_seconds").at("baseline_median"), 2) + " s)";
      md << "| " << g->at("vessel").get<std::string>() << " | "
         << g->at("method").get<std::string>() << " | " << g->at("pairs").get<int>() << " | "
         << Format(g->at("median_fit_percent"), 1) << " | "
         << Format(g->at("baseline_median_fit_percent"), 1) << " | "
         << Format(g->at("median_difference"), 2) << " | " << FormatP(g->at("p_adjusted")) << " | "
         << verdict << " |\n";
    }
    md << '\n';
    for (const nlohmann::json* g : shown)
      for (const auto& c : g->at("newly_failing_cells"))
        md << "- newly failing: " << g->at("vessel").get<std::string>() << " / "
           << g->at("method").get<std::string>() << ", "
           << c.at("train_maneuver").get<std::string>() << " -> "
           << c.at("test_maneuver").get<std::string>() << ", noise " << c.at("noise").get<double>()
           << ", seed " << c.at("seed").get<uint64_t>() << ": "
           << OneLine(c.at("status").get<std::string>()) << '\n';
    if (std::any_of(shown.begin(), shown.end(),
                    [](const nlohmann::json* g) { return g->at("newly_failing").get<int>() > 0; }))
      md << '\n';
  }
  md << "Each cell (training and test maneuver, noise, seed) is paired with the same cell of the "
        "baseline, and the paired differences of the held-out fit of each vessel and method are "
        "tested with a two-sided Wilcoxon signed-rank test, Holm-adjusted over the groups: worse "
        "means a median drop of more than "
     << kMinShiftPoints << " points at adjusted p < " << kAlpha
     << ", or a cell that fitted before and fails now.\n";
  return md.str();
}

namespace {

// The baseline's cells by their key, as `file`'s rows give them.
std::map<PairKey, std::vector<Cell>> BaselineCells(const nlohmann::json& baseline,
                                                   const std::string& file) {
  if (!baseline.is_object() || !baseline.contains("rows") || !baseline["rows"].is_array())
    throw InputError(file + ": not a results.json (no \"rows\" array)");
  std::map<PairKey, std::vector<Cell>> before;
  const nlohmann::json& baseline_rows = baseline["rows"];
  for (size_t i = 0; i < baseline_rows.size(); ++i) {
    const BaselineRow r(baseline_rows[i], i, file);
    Cell cell{r.Get<std::string>("status")};
    if (cell.status == "ok") {
      cell.fit = r.Fit();
      cell.seconds = r.Get<double>("fit_seconds");
    }
    before[{r.Get<std::string>("vessel"), r.Get<std::string>("train_maneuver"),
            r.Get<std::string>("test_maneuver"), r.Get<std::string>("method"),
            r.Get<double>("noise"), r.Get<uint64_t>("seed")}]
        .push_back(cell);
  }
  return before;
}

// The cells of both runs paired by key, grouped by vessel and method.
std::map<GroupKey, Group> PairedGroups(const std::map<PairKey, std::vector<Cell>>& now,
                                       const std::map<PairKey, std::vector<Cell>>& before) {
  std::map<GroupKey, Group> groups;
  for (const auto& [key, cells] : now) {
    Group& g = groups[{std::get<0>(key), std::get<3>(key)}];
    g.cells_now += static_cast<int>(cells.size());
    const auto it = before.find(key);
    const size_t paired = it == before.end() ? 0 : std::min(cells.size(), it->second.size());
    for (size_t i = 0; i < paired; ++i) AddPair(key, cells[i], it->second[i], &g);
    g.only_now += static_cast<int>(cells.size() - paired);
  }
  for (const auto& [key, cells] : before) {
    Group& g = groups[{std::get<0>(key), std::get<3>(key)}];
    g.cells_before += static_cast<int>(cells.size());
    const auto it = now.find(key);
    const size_t paired = it == now.end() ? 0 : std::min(cells.size(), it->second.size());
    g.only_baseline += static_cast<int>(cells.size() - paired);
  }
  return groups;
}

// A group's line of the report: its fit and time tests (p adjusted by Holm) and its verdict.
nlohmann::json GroupJson(const GroupKey& key, const Group& g, const Paired& fit,
                         double fit_p_adjusted, const Paired& time, double time_p_adjusted,
                         const std::string& verdict) {
  const bool tested = fit.pairs > 0;
  return {{"vessel", key.first},
          {"method", key.second},
          {"pairs", fit.pairs},
          {"nonzero_pairs", fit.test.n},
          {"median_fit_percent", JsonNumber(fit.median_now)},
          {"baseline_median_fit_percent", JsonNumber(fit.median_before)},
          {"median_difference", JsonNumber(fit.difference.median)},
          {"difference_q1", JsonNumber(fit.difference.q1)},
          {"difference_q3", JsonNumber(fit.difference.q3)},
          {"p_value", tested ? JsonNumber(fit.test.p_value) : nullptr},
          {"p_adjusted", JsonNumber(fit_p_adjusted)},
          {"newly_failing", g.newly_failing.size()},
          {"newly_failing_cells", g.newly_failing},
          {"newly_ok", g.newly_ok},
          {"failing_both", g.failing_both},
          {"only_now", g.only_now},
          {"only_baseline", g.only_baseline},
          {"fit_seconds",
           {{"pairs", time.pairs},
            {"median", JsonNumber(time.median_now)},
            {"baseline_median", JsonNumber(time.median_before)},
            {"p_value", time.pairs > 0 ? JsonNumber(time.test.p_value) : nullptr},
            {"p_adjusted", JsonNumber(time_p_adjusted)}}},
          {"verdict", verdict}};
}

}  // namespace

RegressionReport CompareWithBaseline(const std::vector<ResultRow>& rows,
                                     const nlohmann::json& baseline, const std::string& file) {
  const std::map<PairKey, std::vector<Cell>> before = BaselineCells(baseline, file);
  std::map<PairKey, std::vector<Cell>> now;
  for (const ResultRow& r : rows)
    now[{r.vessel, r.train_maneuver, r.test_maneuver, r.method, r.noise, r.seed}].push_back(
        {r.status, FitOrWorst(r.mean_fit_percent), r.fit_seconds});
  const std::map<GroupKey, Group> groups = PairedGroups(now, before);

  // Both tests per group, then Holm over the groups that have pairs, per family.
  std::vector<Paired> fits, times;
  std::vector<double> fit_p, time_p;
  for (const auto& [key, g] : groups) {
    fits.push_back(ComparePairs(g.fit_now, g.fit_before));
    std::vector<double> seconds_now, seconds_before;
    for (const auto& [fit, s] : g.seconds) {
      seconds_now.push_back(s.first);
      seconds_before.push_back(s.second);
    }
    times.push_back(ComparePairs(seconds_now, seconds_before));
    if (fits.back().pairs > 0) fit_p.push_back(fits.back().test.p_value);
    if (times.back().pairs > 0) time_p.push_back(times.back().test.p_value);
  }
  const std::vector<double> fit_adjusted = HolmAdjust(fit_p), time_adjusted = HolmAdjust(time_p);

  RegressionReport report;
  size_t i = 0, next_fit = 0, next_time = 0;
  for (const auto& [key, g] : groups) {
    const Paired& fit = fits[i];
    const Paired& time = times[i++];
    const double fit_p_adjusted = fit.pairs > 0 ? fit_adjusted[next_fit++] : kNaN;
    const double time_p_adjusted = time.pairs > 0 ? time_adjusted[next_time++] : kNaN;
    const std::string verdict = Verdict(g, fit, fit_p_adjusted, time, time_p_adjusted);
    if (verdict == "worse fit" || verdict == "slower") ++report.worse;
    report.groups.push_back(GroupJson(key, g, fit, fit_p_adjusted, time, time_p_adjusted, verdict));
  }
  return report;
}

}  // namespace usvid
