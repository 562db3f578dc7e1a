#include "harness/cross_validation_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <variant>

namespace usvid {
namespace {

constexpr char kFreeRun[] = "free_run_fit_percent";
constexpr char kDiameter[] = "tactical_diameter_error_m";
constexpr char kDiameterPercent[] = "tactical_diameter_error_percent";

// The closed-loop criteria shown first, in this order; any other after them by name.
const std::vector<std::string>& LeadingCriteria() {
  static const std::vector<std::string> keys = {"first_overshoot_error_deg",
                                                "second_overshoot_error_deg", kDiameterPercent};
  return keys;
}

std::string Label(const std::string& key) {
  if (key == kFreeRun) return "free-run fit %";
  if (key == "first_overshoot_error_deg") return "zig-zag 1st overshoot abs error deg";
  if (key == "second_overshoot_error_deg") return "zig-zag 2nd overshoot abs error deg";
  if (key == kDiameterPercent) return "tactical diameter abs error % of the measured";
  // steady_rate_error_deg_s -> "steady rate abs error deg/s"
  const size_t at = key.find("_error");
  std::string what = key.substr(0, at), unit = key.substr(std::min(key.size(), at + 7));
  std::ranges::replace(what, '_', ' ');
  std::ranges::replace(unit, '_', '/');
  return what + " abs error" + (unit.empty() ? "" : " " + unit);
}

// first_overshoot_error_deg -> first_overshoot_deg: the criterion an error key is of.
std::string CriterionOf(const std::string& error_key) {
  const size_t at = error_key.find("_error");
  return error_key.substr(0, at) + error_key.substr(at + 6);
}

// A row's value of closed-loop error `key` (the table's key: the diameter's in %), or why it has
// none.
std::variant<double, std::string> ClosedLoopValue(const ResultRow& r, const std::string& key) {
  const std::string error_key = key == kDiameterPercent ? std::string(kDiameter) : key;
  const nlohmann::json& c = r.closed_loop;
  const nlohmann::json e = c.is_object() ? c.value(error_key, nlohmann::json()) : nlohmann::json();
  if (!e.is_number()) {
    const std::string status = c.is_object() ? c.value("status", std::string()) : std::string();
    if (status.starts_with("diverged")) return std::string("replay diverged");
    if (status.starts_with("not replay")) return std::string("not replayed");
    if (status.starts_with("no criteria")) return std::string("no criteria");
    return std::string("no value");
  }
  if (key != kDiameterPercent) return std::abs(e.get<double>());
  const double measured = c["measured"].value("tactical_diameter_m", 0.0);
  if (!(std::abs(measured) > 0)) return std::string("no value");
  return 100.0 * std::abs(e.get<double>()) / std::abs(measured);
}

// The closed-loop error keys (the table's) the record of `r`'s run gives a criterion for.
std::set<std::string> ClosedLoopKeys(const ResultRow& r) {
  std::set<std::string> keys;
  const nlohmann::json& c = r.closed_loop;
  if (!c.is_object() || !c.contains("measured") || !c["measured"].is_object()) return keys;
  for (const auto& [key, _] : c.items()) {
    if (key.find("_error") == std::string::npos) continue;
    const nlohmann::json measured = c["measured"].value(CriterionOf(key), nlohmann::json());
    if (measured.is_number()) keys.insert(key == kDiameter ? kDiameterPercent : key);
  }
  return keys;
}

std::string Number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, std::abs(v) < 10 ? "%.2f" : "%.1f", v);
  return buf;
}

}  // namespace

std::vector<CrossValidatedCriterion> CrossValidationTable(const Suite& suite,
                                                          const std::vector<ResultRow>& rows) {
  std::vector<CrossValidatedCriterion> out;
  if (!suite.cv.On()) return out;
  std::set<std::string> methods;
  std::map<std::string, std::set<std::string>> applies;  // criterion -> runs
  for (const ResultRow& r : rows) {
    methods.insert(r.method);
    applies[kFreeRun].insert(r.test_maneuver);
    for (const std::string& key : ClosedLoopKeys(r)) applies[key].insert(r.test_maneuver);
  }
  std::vector<std::string> keys = {kFreeRun};
  for (const std::string& key : LeadingCriteria())
    if (applies.contains(key)) keys.push_back(key);
  for (const auto& [key, _] : applies)
    if (std::ranges::find(keys, key) == keys.end()) keys.push_back(key);
  for (const std::string& key : keys) {
    CrossValidatedCriterion c;
    c.key = key;
    c.label = Label(key);
    c.higher_is_better = key == kFreeRun;
    for (const std::string& run : suite.test_maneuvers)
      if (applies[key].contains(run)) c.runs.push_back(run);
    for (const std::string& m : methods) {
      CrossValidatedMethod cm;
      cm.method = m;
      for (const std::string& run : c.runs) {
        std::vector<double> v;
        std::string why = "no row";
        for (const ResultRow& r : rows) {
          if (r.method != m || r.test_maneuver != run) continue;
          if (r.status != "ok") {
            why = "failed";
          } else if (r.diverged) {
            why = "diverged";
          } else if (key == kFreeRun) {
            if (std::isfinite(r.mean_fit_percent))
              v.push_back(r.mean_fit_percent);
            else
              why = "no value";
          } else {
            const auto value = ClosedLoopValue(r, key);
            if (const double* x = std::get_if<double>(&value))
              v.push_back(*x);
            else
              why = std::get<std::string>(value);
          }
        }
        if (v.empty()) {
          cm.missing[run] = why;
          continue;
        }
        double sum = 0.0;
        for (double x : v) sum += x;
        cm.values[run] = sum / static_cast<double>(v.size());
      }
      std::vector<double> values;
      for (const std::string& run : c.runs)
        if (cm.values.contains(run)) values.push_back(cm.values[run]);
      cm.mean = BootstrapMean(values);
      c.methods.push_back(std::move(cm));
    }
    out.push_back(std::move(c));
  }
  return out;
}

nlohmann::json CrossValidationJson(const Suite& suite, const std::vector<ResultRow>& rows) {
  nlohmann::json criteria = nlohmann::json::array();
  for (const CrossValidatedCriterion& c : CrossValidationTable(suite, rows)) {
    nlohmann::json methods = nlohmann::json::array();
    for (const CrossValidatedMethod& m : c.methods) {
      nlohmann::json j = {{"method", m.method},
                          {"values", m.values},
                          {"missing", m.missing},
                          {"scored_runs", m.values.size()},
                          {"missing_runs", m.missing.size()}};
      if (m.mean.n > 0) j["mean"] = m.mean.mean;
      if (m.mean.n > 1) j["interval"] = {m.mean.low, m.mean.high};
      methods.push_back(j);
    }
    criteria.push_back({{"criterion", c.key},
                        {"label", c.label},
                        {"higher_is_better", c.higher_is_better},
                        {"runs", c.runs},
                        {"methods", methods}});
  }
  return {{"kind", suite.cv.kind},
          {"runs", suite.test_maneuvers},
          {"bootstrap",
           {{"method", "percentile"},
            {"level", kBootstrapLevel},
            {"resamples", kBootstrapResamples},
            {"seed", kBootstrapSeed},
            {"resampled", "held-out runs"}}},
          {"criteria", criteria}};
}

std::string CrossValidationMarkdown(const Suite& suite, const std::vector<ResultRow>& rows) {
  const std::vector<CrossValidatedCriterion> table = CrossValidationTable(suite, rows);
  if (table.empty()) return "";
  const size_t n = suite.test_maneuvers.size();
  std::ostringstream md;
  md << "## Leave-one-run-out cross-validation\n\nEach of the " << n
     << " runs left out in turn: every method fitted on the other " << n - 1
     << " jointly and scored on the run it left out. Per method and criterion, the mean over the "
        "held-out runs and its "
     << std::lround(100 * kBootstrapLevel) << " % percentile bootstrap interval ("
     << kBootstrapResamples << " resamples of the runs, seed " << kBootstrapSeed
     << "); a run whose fit failed or whose free run diverged, or whose replay gave no value, "
        "is missing for that method, counted and never averaged in. Closed-loop criteria are "
        "absolute errors against the held-out record. A change on measured data is judged "
        "this way, over all runs, never on one (docs/compare.md#cross-validation-over-runs).\n\n"
        "| method |";
  for (const CrossValidatedCriterion& c : table)
    md << ' ' << c.label << " (" << c.runs.size() << (c.runs.size() == 1 ? " run" : " runs")
       << ") |";
  md << "\n| --- |";
  for (size_t i = 0; i < table.size(); ++i) md << " --- |";
  md << '\n';
  auto mean = [](const CrossValidatedMethod& m) {
    if (m.mean.n == 0) return std::string("n/a");
    if (m.mean.n == 1) return Number(m.mean.mean) + " (one run)";
    return Number(m.mean.mean) + " [" + Number(m.mean.low) + ", " + Number(m.mean.high) + "]";
  };
  for (size_t m = 0; m < table.front().methods.size(); ++m) {
    md << "| " << table.front().methods[m].method << " |";
    for (const CrossValidatedCriterion& c : table) {
      const CrossValidatedMethod& cm = c.methods[m];
      md << ' ' << mean(cm);
      if (!cm.missing.empty()) md << " (" << cm.missing.size() << " missing)";
      md << " |";
    }
    md << '\n';
  }
  for (const CrossValidatedCriterion& c : table) {
    md << "\n### " << c.label << ", per held-out run\n\n| run |";
    for (const CrossValidatedMethod& m : c.methods) md << ' ' << m.method << " |";
    md << "\n| --- |";
    for (size_t i = 0; i < c.methods.size(); ++i) md << " --- |";
    md << '\n';
    for (const std::string& run : c.runs) {
      md << "| " << run << " |";
      for (const CrossValidatedMethod& m : c.methods)
        md << ' ' << (m.values.contains(run) ? Number(m.values.at(run)) : m.missing.at(run))
           << " |";
      md << '\n';
    }
    md << "| **mean [" << std::lround(100 * kBootstrapLevel) << " % interval]** |";
    for (const CrossValidatedMethod& m : c.methods) md << ' ' << mean(m) << " |";
    md << "\n| missing runs |";
    for (const CrossValidatedMethod& m : c.methods)
      md << ' ' << m.missing.size() << " of " << c.runs.size() << " |";
    md << '\n';
  }
  return md.str();
}

}  // namespace usvid
