#include "harness/report.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "metrics/evaluation.h"
#include "plot/figure_grid.h"
#include "plot/heat_map.h"
#include "plot/svg_text.h"
#include "simulators/vessel.h"

namespace usvid {
namespace {

std::string FitHeatMap(const Suite& suite, const std::vector<ResultRow>& rows,
                       const std::string& vessel) {
  std::vector<std::string> methods;
  std::map<std::pair<std::string, std::string>, std::vector<double>> fits;
  for (const ResultRow& r : rows) {
    if (r.vessel != vessel) continue;
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
    // As in summary.md: below -100 % counts as -100 % (one diverged run would swamp the mean).
    if (r.status == "ok")
      fits[{r.method, r.test_maneuver}].push_back(std::max(r.mean_fit_percent, -100.0));
  }
  Eigen::MatrixXd values(methods.size(), suite.test_maneuvers.size());
  for (size_t m = 0; m < methods.size(); ++m)
    for (size_t t = 0; t < suite.test_maneuvers.size(); ++t) {
      const auto it = fits.find({methods[m], suite.test_maneuvers[t]});
      double mean = NAN;
      if (it != fits.end() && !it->second.empty()) {
        mean = 0.0;
        for (double f : it->second) mean += f / static_cast<double>(it->second.size());
      }
      values(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(t)) = mean;
    }
  HeatMap map(methods, suite.test_maneuvers, values);
  map.SetTitle(vessel + ": held-out free-run fit (below -100 % counted as -100 %)")
      .SetAxisLabels("method", "test maneuver")
      .SetValueLabel("fit", "%")
      .SetValueRange(0.0, 100.0)
      .SetDecimals(1);
  return map.ToSvg(900, 120 + 60 * static_cast<int>(methods.size()));
}

// One held-out run (test maneuver `test`, first noise level and seed) against every method
// trained on the first training maneuver each could fit.
std::string ExampleRun(const Suite& suite, const std::vector<ResultRow>& rows,
                       const std::string& vessel, const std::string& test) {
  std::map<std::string, const ResultRow*> chosen;  // method -> row
  for (const ResultRow& r : rows)
    if (r.vessel == vessel && r.test_maneuver == test && r.status == "ok" &&
        r.noise == suite.noise.front() && r.seed == suite.seeds.front() && !chosen.count(r.method))
      chosen[r.method] = &r;
  if (chosen.empty()) return "";
  const ResultRow& first = *chosen.begin()->second;
  Dataset held;
  if (suite.Measured()) {
    for (const SuiteData& d : suite.test_data)
      if (d.name == test) held = LoadSuiteData(d);
  } else {
    held = SimulateForSuite(vessel, test, suite.test_seconds, first.noise, first.test_seed);
  }
  std::map<std::string, Evaluation> runs;
  for (const auto& [method, r] : chosen) runs[method] = EvaluateModel(r->model, held);
  // The states the models identify (a vessel model: its dynamic states), and on measured data
  // the heading too.
  std::set<std::string> channels;
  for (const auto& [_, e] : runs)
    for (const std::string& c : e.run.channels)
      if (!IsPositionOrHeading(c) || (suite.Measured() && (c == "psi" || c == "chi")))
        channels.insert(c);
  FigureGrid grid;
  grid.SetTitle(vessel + ", held-out " + test + ": measured and free runs").SetXLabel("t", "s");
  for (const std::string& c : channels) {
    if (!held.Has(c)) continue;
    LinePlot p;
    p.SetYLabel(c).AddSeries("measured", held.t(), held[c]);
    for (const auto& [method, e] : runs)
      if (e.run.simulated.Has(c))
        p.AddSeries(method + " (trained on " + chosen[method]->train_maneuver + ")" +
                        (e.run.diverged ? ", diverged" : ""),
                    held.t(), e.run.simulated[c], SeriesStyle::Dashed());
    grid.Add(std::move(p));
  }
  return grid.ToSvg(1000, 80 + 240 * static_cast<int>(channels.size()));
}

// Markdown tables and headings to HTML, enough for summary.md.
std::string MarkdownToHtml(const std::string& md) {
  std::istringstream in(md);
  std::ostringstream out;
  bool table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("|")) {
      if (line.find("---") != std::string::npos) continue;
      if (!table) out << "<table>\n";
      table = true;
      out << "<tr>";
      std::istringstream cells(line.substr(1));
      for (std::string cell; std::getline(cells, cell, '|');)
        out << "<td>" << svg::Escape(cell) << "</td>";
      out << "</tr>\n";
      continue;
    }
    if (table) out << "</table>\n";
    table = false;
    if (line.starts_with("### ")) {
      out << "<h3>" << svg::Escape(line.substr(4)) << "</h3>\n";
    } else if (line.starts_with("## ")) {
      out << "<h2>" << svg::Escape(line.substr(3)) << "</h2>\n";
    } else if (line.starts_with("# ")) {
      out << "<h1>" << svg::Escape(line.substr(2)) << "</h1>\n";
    } else if (!line.empty()) {
      out << "<p>" << svg::Escape(line) << "</p>\n";
    }
  }
  if (table) out << "</table>\n";
  return out.str();
}

}  // namespace

void WriteReport(const Suite& suite, const std::vector<ResultRow>& rows, const std::string& summary,
                 const std::string& dir) {
  std::set<std::string> vessels;
  for (const ResultRow& r : rows) vessels.insert(r.vessel);
  std::ostringstream html;
  html
      << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>usvid compare: "
      << svg::Escape(suite.name)
      << "</title>\n<style>body{font-family:sans-serif;max-width:1060px;margin:2em auto;color:#222}"
         "table{border-collapse:collapse;margin:1em 0}td{border:1px solid #ccc;padding:3px 8px;"
         "font-size:13px}figure{margin:1.5em 0}</style></head><body>\n";
  html << "<h1>usvid compare: " << svg::Escape(suite.name) << "</h1>\n";
  for (const std::string& vessel : vessels) {
    const std::string heat = FitHeatMap(suite, rows, vessel);
    WriteFileAtomically(dir + "/fit_" + vessel + ".svg", heat);
    html << "<h2>" << svg::Escape(vessel) << "</h2>\n<figure class=\"plot\">" << heat
         << "</figure>\n";
    // Simulated suites: the first test maneuver; measured data: every test file.
    const size_t tests = suite.Measured() ? suite.test_maneuvers.size() : 1;
    for (size_t t = 0; t < tests; ++t) {
      const std::string run = ExampleRun(suite, rows, vessel, suite.test_maneuvers[t]);
      if (run.empty()) continue;
      WriteFileAtomically(
          dir + "/run_" + vessel + (t == 0 ? "" : "_" + std::to_string(t + 1)) + ".svg", run);
      html << "<figure class=\"plot\">" << run << "</figure>\n";
    }
  }
  html << MarkdownToHtml(summary) << "</body></html>\n";
  WriteFileAtomically(dir + "/report.html", html.str());
}

}  // namespace usvid
