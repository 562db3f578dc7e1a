#include "harness/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "harness/cross_validation.h"
#include "methods/nominal/nominal.h"
#include "metrics/rank_tests.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

struct Metric {
  const char* key;
  const char* label;
  bool higher_is_better;
  // The row's score, or nothing when the metric does not apply to its test maneuver.
  std::function<std::optional<double>(const ResultRow&)> score;
};

std::optional<double> Horizon(const ResultRow& r, const char* key) {
  const auto it = r.horizon_fit_percent.find(key);
  if (it == r.horizon_fit_percent.end()) return std::nullopt;
  return it->second;
}

// |model - measured| of a closed-loop criterion; infinite when the replay gave none.
std::optional<double> CriterionError(const ResultRow& r, const char* key) {
  if (!r.closed_loop.is_object() || !r.closed_loop.contains(key)) return std::nullopt;
  const nlohmann::json& e = r.closed_loop[key];
  return e.is_number() ? std::abs(e.get<double>()) : INFINITY;
}

const std::vector<Metric>& Metrics() {
  static const std::vector<Metric> metrics = {
      {"free_run_fit_percent", "free-run fit %", true,
       [](const ResultRow& r) { return std::optional<double>(r.mean_fit_percent); }},
      {"horizon_5s_fit_percent", "5 s horizon fit %", true,
       [](const ResultRow& r) { return Horizon(r, "5"); }},
      {"horizon_30s_fit_percent", "30 s horizon fit %", true,
       [](const ResultRow& r) { return Horizon(r, "30"); }},
      {"first_overshoot_error_deg", "zig-zag 1st overshoot abs error deg", false,
       [](const ResultRow& r) { return CriterionError(r, "first_overshoot_error_deg"); }},
      {"second_overshoot_error_deg", "zig-zag 2nd overshoot abs error deg", false,
       [](const ResultRow& r) { return CriterionError(r, "second_overshoot_error_deg"); }},
      {"tactical_diameter_error_m", "turning tactical diameter abs error m", false,
       [](const ResultRow& r) { return CriterionError(r, "tactical_diameter_error_m"); }},
  };
  return metrics;
}

// noise, seed, and on measured data the test run: there each held-out run is a block of its
// own (the runs are independent records, and a suite on logs has one seed), elsewhere the test
// maneuvers of a cell are averaged ("" here).
using CellKey = std::tuple<double, uint64_t, std::string>;

struct MethodCells {
  std::map<CellKey, double> score;  // mean over the cell's test maneuvers
  int failed = 0, runs = 0, diverged = 0;
};

// Per method, its cells' scores for one metric (a failed fit: the worst score).
std::map<std::string, MethodCells> CellScores(const std::vector<const ResultRow*>& rows,
                                              const Metric& metric, bool per_run) {
  const double worst = metric.higher_is_better ? -INFINITY : INFINITY;
  std::map<std::string, std::map<CellKey, std::vector<double>>> values;
  std::map<std::string, MethodCells> out;
  // Failed cells, counted once: a fit's (its test maneuvers share it), or on measured data a run's.
  std::set<std::tuple<std::string, double, uint64_t, std::string>> failed;
  // The test maneuvers the metric applies to, shown by the rows that were scored on them.
  std::set<std::string> applies;
  for (const ResultRow* r : rows)
    if (r->status == "ok" && metric.score(*r)) applies.insert(r->test_maneuver);
  for (const ResultRow* r : rows) {
    const CellKey cell{r->noise, r->seed, per_run ? r->test_maneuver : std::string()};
    if (r->status != "ok") {
      if (!applies.contains(r->test_maneuver)) continue;
      if (failed.insert({r->method, r->noise, r->seed, std::get<2>(cell)}).second)
        ++out[r->method].failed;
      values[r->method][cell].push_back(worst);
      continue;
    }
    const std::optional<double> v = metric.score(*r);
    if (!v) continue;
    values[r->method][cell].push_back(*v);
    ++out[r->method].runs;
    out[r->method].diverged += r->diverged;
  }
  for (auto& [method, cells] : values)
    for (const auto& [cell, v] : cells) {
      double sum = 0.0;
      for (double x : v) sum += x;
      out[method].score[cell] = sum / static_cast<double>(v.size());
    }
  return out;
}

// The suite's pairs of method names as its rows label the methods (SuiteMethod::Label:
// gp[+,-,*,abs]), every variant of each.
std::vector<std::array<std::string, 2>> PairLabels(const Suite& suite) {
  std::vector<std::array<std::string, 2>> out;
  for (const auto& [first, second] : suite.pairs)
    for (const SuiteMethod& a : suite.methods)
      for (const SuiteMethod& b : suite.methods)
        if (a.method == first && b.method == second) out.push_back({a.Label(), b.Label()});
  return out;
}

// Each pair of labels head to head over the cells both have (PairTest).
std::vector<PairTest> PairTests(const std::vector<std::array<std::string, 2>>& pairs,
                                const std::map<std::string, MethodCells>& cells) {
  std::vector<PairTest> out;
  for (const auto& [a, b] : pairs) {
    const auto a_it = cells.find(a), b_it = cells.find(b);
    if (a_it == cells.end() || b_it == cells.end()) continue;
    const MethodCells& a_cells = a_it->second;
    const MethodCells& b_cells = b_it->second;
    std::vector<double> x, y, difference;
    bool any_value = false;  // a cell where either method has a score (not a failure)
    for (const auto& [cell, score] : a_cells.score) {
      const auto it = b_cells.score.find(cell);
      if (it == b_cells.score.end()) continue;
      any_value = any_value || std::isfinite(score) || std::isfinite(it->second);
      // Two failed cells are equal (no difference), not inf - inf.
      difference.push_back(score == it->second ? 0.0 : score - it->second);
      if (score == it->second) continue;
      x.push_back(score);
      y.push_back(it->second);
    }
    if (!any_value) continue;  // neither has a value: nothing to compare
    PairTest t;
    t.a = a;
    t.b = b;
    t.cells = static_cast<int>(difference.size());
    t.median_difference = Median(difference);
    t.p = x.empty() ? 1.0 : WilcoxonSignedRank(x, y).p_value;
    out.push_back(t);
  }
  return out;
}

VerdictEntry Judge(const std::string& vessel, const std::string& train, const Metric& metric,
                   const std::vector<const ResultRow*>& rows, bool per_run,
                   const std::vector<std::array<std::string, 2>>& pairs) {
  VerdictEntry e;
  e.vessel = vessel;
  e.train_maneuver = train;
  e.metric = metric.key;
  e.label = metric.label;
  e.higher_is_better = metric.higher_is_better;
  std::map<std::string, MethodCells> cells = CellScores(rows, metric, per_run);
  e.pairs = PairTests(pairs, cells);
  if (const auto it = cells.find(std::string(kNominalMethodName)); it != cells.end()) {
    std::vector<double> v;
    for (const auto& [_, s] : it->second.score) v.push_back(s);
    if (!v.empty()) e.ceiling = Median(v);
    cells.erase(it);
  }
  std::vector<std::string> methods;
  for (const auto& [method, c] : cells) {
    if (c.runs == 0) {
      if (c.failed > 0) e.failing.push_back(method);
      continue;
    }
    methods.push_back(method);
  }
  // The cells every ranked method has.
  std::vector<CellKey> common;
  if (!methods.empty())
    for (const auto& [cell, _] : cells[methods.front()].score) {
      bool all = true;
      for (const std::string& m : methods) all = all && cells[m].score.contains(cell);
      if (all) common.push_back(cell);
    }
  e.cells = static_cast<int>(common.size());
  // Scores oriented so that higher is better, per method over the common cells.
  const double sign = metric.higher_is_better ? 1.0 : -1.0;
  std::map<std::string, std::vector<double>> oriented;
  std::vector<std::vector<double>> table(common.size(), std::vector<double>(methods.size()));
  for (size_t m = 0; m < methods.size(); ++m)
    for (size_t c = 0; c < common.size(); ++c) {
      const double v = sign * cells[methods[m]].score[common[c]];
      oriented[methods[m]].push_back(v);
      table[c][m] = v;
    }
  const FriedmanTest friedman =
      common.size() >= 2 && methods.size() >= 2 ? Friedman(table) : FriedmanTest{};
  e.friedman_p = friedman.p_value;
  for (size_t m = 0; m < methods.size(); ++m) {
    Standing s;
    s.method = methods[m];
    std::vector<double> all;
    for (const auto& [_, v] : cells[methods[m]].score) all.push_back(v);
    s.median = Median(all);
    s.mean_rank = friedman.mean_ranks.empty() ? 0.0 : friedman.mean_ranks[m];
    s.cells = static_cast<int>(all.size());
    s.failed = cells[methods[m]].failed;
    s.runs = cells[methods[m]].runs;
    s.diverged = cells[methods[m]].diverged;
    e.ranking.push_back(s);
  }
  std::sort(e.ranking.begin(), e.ranking.end(), [&](const Standing& a, const Standing& b) {
    if (a.mean_rank != b.mean_rank) return a.mean_rank > b.mean_rank;
    return sign * a.median > sign * b.median;
  });
  if (e.ranking.size() < 2 || common.size() < 2) return e;
  std::vector<double> vs_best, vs_previous;
  for (size_t i = 1; i < e.ranking.size(); ++i) {
    const std::vector<double>& a = oriented[e.ranking[0].method];
    vs_best.push_back(WilcoxonSignedRank(a, oriented[e.ranking[i].method]).p_value);
    vs_previous.push_back(
        WilcoxonSignedRank(oriented[e.ranking[i - 1].method], oriented[e.ranking[i].method])
            .p_value);
  }
  vs_best = HolmAdjust(vs_best);
  vs_previous = HolmAdjust(vs_previous);
  const bool differ = e.friedman_p < kVerdictAlpha;
  for (size_t i = 1; i < e.ranking.size(); ++i) {
    e.ranking[i].p_vs_best = vs_best[i - 1];
    e.ranking[i].tied_with_best = !differ || vs_best[i - 1] >= kVerdictAlpha;
    e.ranking[i].tied_with_previous = !differ || vs_previous[i - 1] >= kVerdictAlpha;
  }
  return e;
}

std::string Number(double v) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, std::abs(v) < 10 ? "%.2f" : "%.1f", v);
  return buf;
}

std::string PValue(double p) {
  char buf[32];
  std::snprintf(buf, sizeof buf, p < 0.001 ? "%.1e" : "%.3f", p);
  return buf;
}

}  // namespace

std::vector<VerdictEntry> Verdict(const Suite& suite, const std::vector<ResultRow>& rows) {
  std::vector<VerdictEntry> out;
  std::set<std::string> vessels;
  for (const ResultRow& r : rows) vessels.insert(r.vessel);
  const std::vector<std::array<std::string, 2>> pairs = PairLabels(suite);
  for (const std::string& vessel : vessels)
    for (const std::string& train : TrainingLabels(suite)) {
      std::vector<const ResultRow*> cell_rows;
      for (const ResultRow& r : rows)
        if (r.vessel == vessel && r.train_maneuver == train) cell_rows.push_back(&r);
      if (cell_rows.empty()) continue;
      for (const Metric& metric : Metrics()) {
        VerdictEntry e = Judge(vessel, train, metric, cell_rows, suite.Measured(), pairs);
        if (!e.ranking.empty()) out.push_back(std::move(e));
      }
    }
  return out;
}

nlohmann::json VerdictJson(const std::vector<VerdictEntry>& verdict) {
  nlohmann::json out = nlohmann::json::array();
  for (const VerdictEntry& e : verdict) {
    nlohmann::json ranking = nlohmann::json::array();
    for (const Standing& s : e.ranking)
      ranking.push_back({{"method", s.method},
                         {"median", std::isfinite(s.median) ? nlohmann::json(s.median) : nullptr},
                         {"mean_rank", s.mean_rank},
                         {"cells", s.cells},
                         {"failed_cells", s.failed},
                         {"runs", s.runs},
                         {"diverged_runs", s.diverged},
                         {"p_vs_best", s.p_vs_best},
                         {"tied_with_best", s.tied_with_best},
                         {"tied_with_previous", s.tied_with_previous}});
    nlohmann::json j = {{"vessel", e.vessel},
                        {"train_maneuver", e.train_maneuver},
                        {"metric", e.metric},
                        {"label", e.label},
                        {"higher_is_better", e.higher_is_better},
                        {"cells", e.cells},
                        {"friedman_p", e.friedman_p},
                        {"ranking", ranking},
                        {"failing", e.failing}};
    if (!e.pairs.empty()) {
      nlohmann::json pairs = nlohmann::json::array();
      for (const PairTest& t : e.pairs)
        pairs.push_back(
            {{"a", t.a},
             {"b", t.b},
             {"cells", t.cells},
             {"median_difference", std::isfinite(t.median_difference)
                                       ? nlohmann::json(t.median_difference)
                                       : nlohmann::json(t.median_difference > 0 ? "inf" : "-inf")},
             {"p", t.p}});
      j["pairs"] = pairs;
    }
    if (e.ceiling)
      j[std::string(kNominalMethodName)] =
          std::isfinite(*e.ceiling) ? nlohmann::json(*e.ceiling) : nullptr;
    out.push_back(j);
  }
  return out;
}

std::string VerdictMarkdown(const std::vector<VerdictEntry>& verdict) {
  std::ostringstream md;
  std::string heading;
  // The pairs' lines of the table being written: "a against b" -> "metric +1.2 (p ..)" items.
  std::vector<std::pair<std::string, std::vector<std::string>>> pairs;
  auto flush_pairs = [&] {
    if (!pairs.empty()) md << "\n";
    for (const auto& [who, items] : pairs) {
      md << "- **" << who << "** (median of the paired differences over the cells both have; "
         << "two-sided Wilcoxon p, not adjusted):";
      for (size_t i = 0; i < items.size(); ++i) md << (i ? "; " : " ") << items[i];
      md << "\n";
    }
    pairs.clear();
  };
  for (const VerdictEntry& e : verdict) {
    const std::string h = VesselLabel(e.vessel) + ", trained on " + e.train_maneuver;
    if (h != heading) {
      flush_pairs();
      heading = h;
      md << "\n### " << h << "\n\n| metric | ranking, best first (**bold**: tied with the best; "
         << "=: the data cannot tell the two apart) | Friedman p | cells | nominal |\n"
         << "| --- | --- | --- | --- | --- |\n";
    }
    md << "| " << e.label << " | ";
    for (size_t i = 0; i < e.ranking.size(); ++i) {
      const Standing& s = e.ranking[i];
      if (i > 0) md << (s.tied_with_previous ? " = " : " > ");
      md << (s.tied_with_best ? "**" + s.method + "**" : s.method) << ' ';
      // Half or more of the cells failed, diverged or gave no criterion: no number to show.
      md << (std::isfinite(s.median) ? Number(s.median) : std::string("no median"));
      if (s.diverged > 0 && e.metric == "free_run_fit_percent")
        md << " (" << s.diverged << "/" << s.runs << " diverged)";
      if (s.failed > 0) md << " (" << s.failed << " of " << s.cells << " cells failed)";
    }
    for (const std::string& m : e.failing) md << "; " << m << " failed in every cell";
    md << " | " << PValue(e.friedman_p) << " | " << e.cells << " | "
       << (e.ceiling ? Number(*e.ceiling) : "") << " |\n";
    for (const PairTest& t : e.pairs) {
      const std::string who = t.a + " against " + t.b;
      auto it =
          std::find_if(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first == who; });
      if (it == pairs.end()) it = pairs.insert(pairs.end(), {who, {}});
      // An infinite median: the worse method failed, diverged or gave no criterion in most cells.
      const bool a_worse = (t.median_difference < 0) == e.higher_is_better;
      const std::string difference =
          std::isfinite(t.median_difference)
              ? (t.median_difference > 0 ? "+" : "") + Number(t.median_difference)
              : (a_worse ? t.a : t.b) + " has no value in most cells";
      it->second.push_back(e.label + " " + difference + " (p " + PValue(t.p) + ", " +
                           std::to_string(t.cells) + (t.cells == 1 ? " cell)" : " cells)"));
    }
  }
  flush_pairs();
  return md.str();
}

}  // namespace usvid
