#include "harness/results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "core/parse_number.h"

namespace usvid {
namespace {

// In the tables a fit below -100 % counts as -100 %: such a free run is useless either way, and
// one diverged run at -1e5 % would otherwise swamp every mean. results.json keeps the raw values.
constexpr double kFitFloor = -100.0;

struct Stats {
  double mean = 0.0, sd = 0.0;
  int n = 0;
};

Stats Of(const std::vector<double>& v) {
  Stats s;
  s.n = static_cast<int>(v.size());
  if (v.empty()) return s;
  for (double x : v) s.mean += x / s.n;
  for (double x : v) s.sd += (x - s.mean) * (x - s.mean) / std::max(1, s.n - 1);
  s.sd = std::sqrt(s.sd);
  return s;
}

std::string Cell(const Stats& s) {
  if (s.n == 0) return "n/a";
  char buf[64];
  if (std::abs(s.mean) < 10 && s.mean != std::round(s.mean)) {
    std::snprintf(buf, sizeof buf, "%.2f ± %.2f", s.mean, s.sd);
  } else {
    std::snprintf(buf, sizeof buf, "%.1f ± %.1f", s.mean, s.sd);
  }
  return buf;
}

template <typename Key>
std::map<Key, std::vector<double>> Group(const std::vector<ResultRow>& rows,
                                         const std::function<bool(const ResultRow&)>& keep,
                                         const std::function<Key(const ResultRow&)>& key) {
  std::map<Key, std::vector<double>> g;
  for (const ResultRow& r : rows)
    if (r.status == "ok" && keep(r)) g[key(r)].push_back(std::max(r.mean_fit_percent, kFitFloor));
  return g;
}

// On measured data: per test maneuver, method x channel (heading and positions too), the
// free-run fit % (mean ± sd over seeds).
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
            by[c].push_back(std::max(fit, kFitFloor));
      if (by.empty()) continue;
      md << "| " << m << " |";
      for (const std::string& c : channels)
        md << ' ' << Cell(by.contains(c) ? Of(by[c]) : Stats{}) << " |";
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

}  // namespace

nlohmann::json ResultsJson(const Suite& suite, const std::vector<ResultRow>& rows, double seconds) {
  nlohmann::json r = nlohmann::json::array();
  for (const ResultRow& row : rows) r.push_back(row.ToJson());
  return {{"suite", SuiteToJson(suite)}, {"seconds", seconds}, {"rows", r}};
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
     << std::lround(seconds) << " s. Numbers: free-run fit % on held-out data (another maneuver, "
     << "or the same with another seed), mean over the identified states, then mean ± sd over "
        "seeds and noise levels; fits below -100 % count as -100 % in the tables (results.json "
        "has the raw values).\n\n";
  std::set<std::string> methods, vessels;
  for (const ResultRow& r : rows) {
    methods.insert(r.method);
    vessels.insert(r.vessel);
  }
  for (const std::string& vessel : vessels) {
    md << "## " << vessel << "\n\n### Method x test maneuver\n\n| method |";
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
        md << ' ' << Cell(it == g.end() ? Stats{} : Of(it->second)) << " |";
      }
      md << '\n';
    }
    if (suite.Measured()) PerChannelTables(suite, rows, vessel, methods, md);
    // Structure and complexity per method, over every scored row of this vessel.
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
      md << "| " << m << " | " << Cell(Of(prec[m])) << " | " << Cell(Of(rec[m])) << " | "
         << Cell(Of(t)) << " | " << Cell(Of(perr[m])) << " |\n";
    md << "\n### Training x test maneuver, per method (generalisation)\n\n";
    for (const std::string& m : methods) {
      const auto gm = Group<std::pair<std::string, std::string>>(
          rows, [&](const ResultRow& r) { return r.vessel == vessel && r.method == m; },
          [](const ResultRow& r) { return std::make_pair(r.train_maneuver, r.test_maneuver); });
      if (gm.empty()) continue;
      md << "**" << m << "**\n\n| trained on \\ tested on |";
      for (const std::string& t : suite.test_maneuvers) md << ' ' << t << " |";
      md << "\n| --- |";
      for (size_t i = 0; i < suite.test_maneuvers.size(); ++i) md << " --- |";
      md << '\n';
      std::string best;
      double best_other = -INFINITY;
      for (const std::string& train : suite.train_maneuvers) {
        bool any = false;
        for (const std::string& t : suite.test_maneuvers) any = any || gm.count({train, t});
        if (!any) continue;
        md << "| " << train << " |";
        std::vector<double> others;
        for (const std::string& t : suite.test_maneuvers) {
          const auto it = gm.find({train, t});
          md << ' ' << Cell(it == gm.end() ? Stats{} : Of(it->second)) << " |";
          if (it != gm.end() && t != train)
            others.insert(others.end(), it->second.begin(), it->second.end());
        }
        md << '\n';
        const Stats o = Of(others);
        if (o.n > 0 && o.mean > best_other) {
          best_other = o.mean;
          best = train;
        }
      }
      if (!best.empty()) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.1f", best_other);
        md << "\nBest training maneuver for " << m << " on " << vessel << ": **" << best
           << "** (mean fit " << buf << " % on the other maneuvers).\n";
      }
      md << '\n';
    }
  }
  // The maneuver design question per speed regime: which training maneuver gives the best
  // held-out fit on the rows of the other test maneuvers in each regime.
  md << "## Best training maneuver per speed regime\n\n| vessel | method | displacement | "
        "semi-displacement | planing |\n| --- | --- | --- | --- | --- |\n";
  for (const std::string& vessel : vessels)
    for (const std::string& m : methods) {
      std::map<std::string, std::map<std::string, std::vector<double>>> by;  // regime, train
      for (const ResultRow& r : rows)
        if (r.vessel == vessel && r.method == m && r.status == "ok" &&
            r.train_maneuver != r.test_maneuver)
          for (const auto& [regime, fit] : r.regime_fit_percent)
            by[regime][r.train_maneuver].push_back(std::max(fit, kFitFloor));
      if (by.empty()) continue;
      md << "| " << vessel << " | " << m << " |";
      for (const char* regime : {"displacement", "semi-displacement", "planing"}) {
        std::string best = "n/a";
        double best_fit = -INFINITY;
        for (const auto& [train, fits] : by[regime]) {
          const Stats st = Of(fits);
          if (st.mean > best_fit) {
            best_fit = st.mean;
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s (%.1f)", train.c_str(), st.mean);
            best = buf;
          }
        }
        md << ' ' << best << " |";
      }
      md << '\n';
    }
  md << '\n';
  if (failed > 0) {
    md << "## Failed\n\n";
    std::set<std::string> seen;
    for (const ResultRow& r : rows)
      if (r.status != "ok" && seen.insert(r.vessel + r.train_maneuver + r.method + r.status).second)
        md << "- " << r.vessel << " / " << r.train_maneuver << " / " << r.method << ": " << r.status
           << '\n';
  }
  return md.str();
}

}  // namespace usvid
