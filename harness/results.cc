#include "harness/results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "core/parse_number.h"
#include "harness/cross_validation.h"
#include "harness/cross_validation_table.h"
#include "harness/verdict.h"
#include "metrics/rank_tests.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// Table cells: the median and, over more than two values, the interquartile range. Rank-based,
// so a diverged run's fit of -1e5 % needs no clamping: it moves the median by one place.
std::string Cell(const std::vector<double>& v) {
  if (v.empty()) return "n/a";
  const Spread s = Describe(v);
  auto number = [](double x) {
    char buf[32];
    if (!std::isfinite(x)) return std::string(x > 0 ? "inf" : "-inf");
    std::snprintf(buf, sizeof buf, std::abs(x) < 10 && x != std::round(x) ? "%.2f" : "%.1f", x);
    return std::string(buf);
  };
  if (s.n <= 2) return number(s.median);
  return number(s.median) + " [" + number(s.q1) + ", " + number(s.q3) + "]";
}

template <typename Key>
std::map<Key, std::vector<double>> Group(const std::vector<ResultRow>& rows,
                                         const std::function<bool(const ResultRow&)>& keep,
                                         const std::function<Key(const ResultRow&)>& key) {
  std::map<Key, std::vector<double>> g;
  for (const ResultRow& r : rows)
    if (r.status == "ok" && keep(r)) g[key(r)].push_back(r.mean_fit_percent);
  return g;
}

// On measured data: per test maneuver, method x channel (heading and positions too), the
// free-run fit % (median over seeds).
void PerChannelTables(const Suite& suite, const std::vector<ResultRow>& rows,
                      const std::string& vessel, const std::set<std::string>& methods,
                      std::ostringstream& md) {
  std::vector<std::string> channels;
  auto add = [&channels](const std::string& c) {
    if (std::find(channels.begin(), channels.end(), c) == channels.end()) channels.push_back(c);
  };
  std::set<std::string> present;
  for (const ResultRow& r : rows)
    for (const auto& [c, _] : r.channel_fit_percent) present.insert(c);
  for (const char* c : {"r", "psi", "u", "v", "U", "chi", "north", "east"})
    if (present.contains(c)) add(c);
  for (const std::string& c : present) add(c);
  for (const std::string& test : suite.test_maneuvers) {
    md << "\n### " << test << ": free-run fit % per channel\n\n| method |";
    for (const std::string& c : channels) md << ' ' << c << " |";
    md << "\n| --- |";
    for (size_t i = 0; i < channels.size(); ++i) md << " --- |";
    md << '\n';
    for (const std::string& m : methods) {
      std::map<std::string, std::vector<double>> by;
      for (const ResultRow& r : rows)
        if (r.vessel == vessel && r.method == m && r.test_maneuver == test && r.status == "ok")
          for (const auto& [c, fit] : r.channel_fit_percent)
            by[c].push_back(fit);
      if (by.empty()) continue;
      md << "| " << m << " |";
      for (const std::string& c : channels)
        md << ' ' << Cell(by.contains(c) ? by[c] : std::vector<double>{}) << " |";
      md << '\n';
    }
  }
  md << '\n';
}

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}


// The headline tables: per training maneuver (never pooled), per method the median
// [interquartile range] over its test rows of each score, and how many runs diverged or failed.
void HeadlineTables(const Suite& suite, const std::vector<ResultRow>& rows,
                    const std::string& vessel, const std::set<std::string>& methods,
                    std::ostringstream& md) {
  for (const std::string& train : TrainingLabels(suite)) {
    bool header = false;
    for (const std::string& m : methods) {
      std::vector<double> fit, h5, h30, vpt, r2, overshoot;
      int runs = 0, diverged = 0, failed = 0;
      for (const ResultRow& r : rows) {
        if (r.vessel != vessel || r.train_maneuver != train || r.method != m) continue;
        ++runs;
        if (r.status != "ok") {
          ++failed;
          continue;
        }
        diverged += r.diverged;
        fit.push_back(r.mean_fit_percent);
        if (r.horizon_fit_percent.contains("5")) h5.push_back(r.horizon_fit_percent.at("5"));
        if (r.horizon_fit_percent.contains("30")) h30.push_back(r.horizon_fit_percent.at("30"));
        if (r.valid_prediction_s) vpt.push_back(*r.valid_prediction_s);
        if (!r.derivative_r2.empty()) {
          double sum = 0.0;
          for (const auto& [_, v] : r.derivative_r2) sum += v;
          r2.push_back(sum / static_cast<double>(r.derivative_r2.size()));
        }
        if (r.closed_loop.contains("first_overshoot_error_deg")) {
          const nlohmann::json& e = r.closed_loop["first_overshoot_error_deg"];
          overshoot.push_back(e.is_number() ? std::abs(e.get<double>()) : INFINITY);
        }
      }
      if (runs == 0) continue;
      if (!header) {
        md << "\n### Trained on " << train
           << "\n\n| method | free-run fit % | 5 s horizon fit % | 30 s horizon fit % | valid "
              "prediction s | derivative R^2 | zig-zag 1st overshoot abs error deg | diverged | "
              "failed |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
        header = true;
      }
      md << "| " << m << " | " << Cell(fit) << " | " << Cell(h5) << " | " << Cell(h30) << " | "
         << Cell(vpt) << " | " << Cell(r2) << " | " << Cell(overshoot) << " | " << diverged << "/"
         << (runs - failed) << " | " << failed << "/" << runs << " |\n";
    }
  }
}

// Per closed-loop test maneuver: the criteria of the held-out records and of each model's
// replay (medians over the rows; "replayed": replays that gave the criteria).
void ClosedLoopTables(const Suite& suite, const std::vector<ResultRow>& rows,
                      const std::string& vessel, const std::set<std::string>& methods,
                      std::ostringstream& md) {
  for (const std::string& test : suite.test_maneuvers) {
    std::vector<std::string> criteria;
    std::map<std::string, std::map<std::string, std::vector<double>>> values;  // who, criterion
    std::map<std::string, std::pair<int, int>> replayed;                       // ok, all
    std::string not_replayable;
    for (const ResultRow& r : rows) {
      if (r.vessel != vessel || r.test_maneuver != test || r.status != "ok") continue;
      const nlohmann::json& c = r.closed_loop;
      if (!c.contains("measured")) {
        if (c.contains("status")) not_replayable = c["status"].get<std::string>();
        continue;
      }
      auto& [ok, all] = replayed[r.method];
      ++all;
      ok += c["status"] == "ok";
      for (const auto& [name, v] : c["measured"].items()) {
        if (std::ranges::find(criteria, name) == criteria.end()) criteria.push_back(name);
        if (v.is_number()) values["measured"][name].push_back(v.get<double>());
        const nlohmann::json& m = c["model"][name];
        if (m.is_number()) values[r.method][name].push_back(m.get<double>());
      }
    }
    if (criteria.empty()) {
      if (suite.Measured() && !not_replayable.empty())
        md << "\n" << test << ": " << not_replayable << ".\n";
      continue;
    }
    md << "\n### " << test << ": closed-loop criteria (the maneuver re-run on each model)\n\n| |";
    for (const std::string& c : criteria) md << ' ' << c << " |";
    md << " replayed |\n| --- |";
    for (size_t i = 0; i <= criteria.size(); ++i) md << " --- |";
    md << "\n| measured |";
    for (const std::string& c : criteria) md << ' ' << Cell(values["measured"][c]) << " |";
    md << " |\n";
    for (const std::string& m : methods) {
      if (!replayed.contains(m)) continue;
      md << "| " << m << " |";
      for (const std::string& c : criteria) md << ' ' << Cell(values[m][c]) << " |";
      md << ' ' << replayed[m].first << "/" << replayed[m].second << " |\n";
    }
  }
}

// Per method, the median fit of each test maneuver, pooled over training maneuvers, noise and
// seeds.
void MethodByTestTable(const Suite& suite, const std::vector<ResultRow>& rows,
                       const std::string& vessel, const std::set<std::string>& methods,
                       std::ostringstream& md) {
  md << "\n### Method x test maneuver (pooled over training maneuvers, noise and seeds)\n\n"
        "| method |";
  for (const std::string& t : suite.test_maneuvers) md << ' ' << t << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < suite.test_maneuvers.size(); ++i) md << " --- |";
  md << '\n';
  const auto g = Group<std::pair<std::string, std::string>>(
      rows, [&](const ResultRow& r) { return r.vessel == vessel; },
      [](const ResultRow& r) { return std::make_pair(r.method, r.test_maneuver); });
  for (const std::string& m : methods) {
    bool any = false;
    for (const std::string& t : suite.test_maneuvers) any = any || g.count({m, t});
    if (!any) continue;
    md << "| " << m << " |";
    for (const std::string& t : suite.test_maneuvers) {
      const auto it = g.find({m, t});
      md << ' ' << Cell(it == g.end() ? std::vector<double>{} : it->second) << " |";
    }
    md << '\n';
  }
}

// Structure and complexity per method, over every scored row of this vessel.
void StructureTable(const std::vector<ResultRow>& rows, const std::string& vessel,
                    std::ostringstream& md) {
  std::map<std::string, std::vector<double>> prec, rec, terms, perr;
  for (const ResultRow& r : rows) {
    if (r.vessel != vessel || r.status != "ok") continue;
    terms[r.method].push_back(r.terms);
    if (r.precision) prec[r.method].push_back(*r.precision);
    if (r.recall) rec[r.method].push_back(*r.recall);
    if (r.parameter_error) perr[r.method].push_back(100.0 * *r.parameter_error);
  }
  md << "\n### Structure (term precision / recall against the true equations), size, "
        "parameter error\n\n| method | precision | recall | terms | worst parameter error % |\n"
        "| --- | --- | --- | --- | --- |\n";
  for (const auto& [m, t] : terms)
    md << "| " << m << " | " << Cell(prec[m]) << " | " << Cell(rec[m]) << " | " << Cell(t) << " | "
       << Cell(perr[m]) << " |\n";
}

// One method's table of training x test maneuver, and the training maneuver with the best
// median fit on the other maneuvers.
void GeneralisationTable(const Suite& suite, const std::vector<ResultRow>& rows,
                         const std::string& vessel, const std::string& m, std::ostringstream& md) {
  const auto gm = Group<std::pair<std::string, std::string>>(
      rows, [&](const ResultRow& r) { return r.vessel == vessel && r.method == m; },
      [](const ResultRow& r) { return std::make_pair(r.train_maneuver, r.test_maneuver); });
  if (gm.empty()) return;
  md << "**" << m << "**\n\n| trained on \\ tested on |";
  for (const std::string& t : suite.test_maneuvers) md << ' ' << t << " |";
  md << "\n| --- |";
  for (size_t i = 0; i < suite.test_maneuvers.size(); ++i) md << " --- |";
  md << '\n';
  std::string best;
  double best_other = -INFINITY;
  for (const std::string& train : TrainingLabels(suite)) {
    bool any = false;
    for (const std::string& t : suite.test_maneuvers) any = any || gm.count({train, t});
    if (!any) continue;
    md << "| " << train << " |";
    std::vector<double> others;
    for (const std::string& t : suite.test_maneuvers) {
      const auto it = gm.find({train, t});
      md << ' ' << Cell(it == gm.end() ? std::vector<double>{} : it->second) << " |";
      if (it != gm.end() && t != train)
        others.insert(others.end(), it->second.begin(), it->second.end());
    }
    md << '\n';
    if (!others.empty() && Median(others) > best_other) {
      best_other = Median(others);
      best = train;
    }
  }
  if (!best.empty()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f", best_other);
    md << "\nBest training maneuver for " << m << " on " << VesselLabel(vessel) << ": **" << best
       << "** (median fit " << buf << " % on the other maneuvers).\n";
  }
  md << '\n';
}

// The maneuver design question per speed regime: which training maneuver gives the best
// median held-out fit on the rows of the other test maneuvers in each regime.
void BestPerRegimeTable(const std::vector<ResultRow>& rows, const std::set<std::string>& vessels,
                        const std::set<std::string>& methods, std::ostringstream& md) {
  md << "## Best training maneuver per speed regime\n\n| vessel | method | displacement | "
        "semi-displacement | planing |\n| --- | --- | --- | --- | --- |\n";
  for (const std::string& vessel : vessels)
    for (const std::string& m : methods) {
      std::map<std::string, std::map<std::string, std::vector<double>>> by;  // regime, train
      for (const ResultRow& r : rows)
        if (r.vessel == vessel && r.method == m && r.status == "ok" &&
            r.train_maneuver != r.test_maneuver)
          for (const auto& [regime, fit] : r.regime_fit_percent)
            by[regime][r.train_maneuver].push_back(fit);
      if (by.empty()) continue;
      md << "| " << VesselLabel(vessel) << " | " << m << " |";
      for (const char* regime : {"displacement", "semi-displacement", "planing"}) {
        std::string best = "n/a";
        double best_fit = -INFINITY;
        for (const auto& [train, fits] : by[regime]) {
          const double median = Median(fits);
          if (median > best_fit) {
            best_fit = median;
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s (%.1f)", train.c_str(), median);
            best = buf;
          }
        }
        md << ' ' << best << " |";
      }
      md << '\n';
    }
  md << '\n';
}

// Each distinct failure (vessel, training maneuver, method and message) once.
void FailedList(const std::vector<ResultRow>& rows, std::ostringstream& md) {
  md << "## Failed\n\n";
  std::set<std::string> seen;
  for (const ResultRow& r : rows)
    if (r.status != "ok" && seen.insert(r.vessel + r.train_maneuver + r.method + r.status).second)
      md << "- " << VesselLabel(r.vessel) << " / " << r.train_maneuver << " / " << r.method << ": " << r.status
         << '\n';
}

}  // namespace

nlohmann::json ResultsJson(const Suite& suite, const std::vector<ResultRow>& rows, double seconds) {
  nlohmann::json r = nlohmann::json::array();
  for (const ResultRow& row : rows) r.push_back(row.ToJson());
  nlohmann::json out = {{"suite", SuiteToJson(suite)},
                        {"seconds", seconds},
                        {"verdict", VerdictJson(Verdict(suite, rows))},
                        {"rows", r}};
  if (suite.cv.On()) out["cross_validation"] = CrossValidationJson(suite, rows);
  return out;
}

std::string ResultsCsv(const std::vector<ResultRow>& rows) {
  std::set<std::string> states;
  for (const ResultRow& r : rows)
    for (const auto& [s, _] : r.fit_percent) states.insert(s);
  std::ostringstream out;
  out << "vessel,train_maneuver,test_maneuver,method,inputs,noise,seed,test_seed,status,diverged,"
         "fit_seconds,mean_fit_percent,terms,structure_precision,structure_recall,parameter_error";
  for (const std::string& s : states) out << ",fit_percent_" << s;
  out << '\n';
  for (const ResultRow& r : rows) {
    const bool ok = r.status == "ok";
    std::string status = ok ? "ok" : "failed";
    out << CsvField(r.vessel) << ',' << CsvField(r.train_maneuver) << ','
        << CsvField(r.test_maneuver) << ',' << CsvField(r.method) << ',' << CsvField(r.inputs)
        << ',' << FormatNumber(r.noise) << ',' << r.seed << ',' << r.test_seed << ',' << status
        << ',' << (ok ? (r.diverged ? "true" : "false") : "") << ','
        << (ok ? FormatNumber(r.fit_seconds) : "") << ','
        << (ok ? FormatNumber(r.mean_fit_percent) : "") << ','
        << (ok ? std::to_string(r.terms) : "") << ','
        << (ok && r.precision ? FormatNumber(*r.precision) : "") << ','
        << (ok && r.recall ? FormatNumber(*r.recall) : "") << ','
        << (ok && r.parameter_error ? FormatNumber(*r.parameter_error) : "");
    for (const std::string& s : states) {
      out << ',';
      const auto it = r.fit_percent.find(s);
      if (ok && it != r.fit_percent.end()) out << FormatNumber(it->second);
    }
    out << '\n';
  }
  return out.str();
}

std::string SummaryMarkdown(const Suite& suite, const std::vector<ResultRow>& rows,
                            double seconds) {
  std::ostringstream md;
  md << "# usvid compare: " << suite.name << "\n\n";
  int failed = 0, diverged = 0;
  for (const ResultRow& r : rows) {
    failed += r.status != "ok";
    diverged += r.status == "ok" && r.diverged;
  }
  md << rows.size() << " scores (" << failed << " failed, " << diverged << " diverged) in "
     << std::lround(seconds)
     << " s. Every score is on held-out data (another maneuver, or the same with another seed). "
        "Fits are the free-run fit % averaged over the identified states; tables give the "
        "median [interquartile range] of the raw values (results.json has every row).\n\n";
  md << "## Verdict\n\nPer vessel, training maneuver and metric: each method's cell score ("
     << (suite.cv.On()      ? "a held-out run, scored by the fit that left it out"
         : suite.Measured() ? "a held-out run and seed"
                            : "a noise level and seed; its test maneuvers averaged")
     << "), the methods ranked by a Friedman "
        "test over the paired cells, each against the best and the next by Wilcoxon "
        "signed-rank tests, Holm-adjusted, at "
     << kVerdictAlpha << ". The medians shown are of the cell scores; nominal "
     << (suite.Measured() ? "(the vessel as given, unfitted) is shown apart, as a baseline"
                          : "(the true simulator) is the ceiling")
     << ".\n"
     << VerdictMarkdown(Verdict(suite, rows)) << '\n';
  if (suite.cv.On()) md << CrossValidationMarkdown(suite, rows) << '\n';
  std::set<std::string> methods, vessels;
  for (const ResultRow& r : rows) {
    methods.insert(r.method);
    vessels.insert(r.vessel);
  }
  for (const std::string& vessel : vessels) {
    md << "## " << VesselLabel(vessel) << "\n";
    HeadlineTables(suite, rows, vessel, methods, md);
    ClosedLoopTables(suite, rows, vessel, methods, md);
    MethodByTestTable(suite, rows, vessel, methods, md);
    if (suite.Measured()) PerChannelTables(suite, rows, vessel, methods, md);
    StructureTable(rows, vessel, md);
    md << "\n### Training x test maneuver, per method (generalisation)\n\n";
    for (const std::string& m : methods) GeneralisationTable(suite, rows, vessel, m, md);
  }
  BestPerRegimeTable(rows, vessels, methods, md);
  if (failed > 0) FailedList(rows, md);
  return md.str();
}

}  // namespace usvid
