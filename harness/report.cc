#include "harness/report.h"

#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/parallel_for.h"
#include "harness/markdown_html.h"
#include "harness/plan_view.h"
#include "methods/nominal/nominal.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/evaluation.h"
#include "metrics/rank_tests.h"
#include "plot/figure_grid.h"
#include "plot/heat_map.h"
#include "plot/svg_text.h"
#include "simulation/vessel_simulator.h"
#include "simulators/vessel.h"

namespace usvid {
namespace {

// Method x test maneuver: the median held-out free-run fit (rank-based: diverged runs need no
// clamping). The colour scale runs from the lowest median (at most 0, at least -100: lower ones
// take its colour, their labels say how low) to 100 %.
std::string FitHeatMap(const Suite& suite, const std::vector<ResultRow>& rows,
                       const std::string& vessel) {
  std::vector<std::string> methods;
  std::map<std::pair<std::string, std::string>, std::vector<double>> fits;
  for (const ResultRow& r : rows) {
    if (r.vessel != vessel) continue;
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
    if (r.status == "ok") fits[{r.method, r.test_maneuver}].push_back(r.mean_fit_percent);
  }
  Eigen::MatrixXd values(methods.size(), suite.test_maneuvers.size());
  double lowest = 0.0;
  for (size_t m = 0; m < methods.size(); ++m)
    for (size_t t = 0; t < suite.test_maneuvers.size(); ++t) {
      const auto it = fits.find({methods[m], suite.test_maneuvers[t]});
      const double median = it == fits.end() ? NAN : Median(it->second);
      if (std::isfinite(median)) lowest = std::min(lowest, std::max(median, -100.0));
      values(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(t)) = median;
    }
  HeatMap map(methods, suite.test_maneuvers, values);
  map.SetTitle(VesselLabel(vessel) +
               ": held-out free-run fit, median over training maneuvers, noise, seeds")
      .SetAxisLabels("method", "test maneuver")
      .SetValueLabel("fit", "%")
      .SetValueRange(lowest, 100.0)
      .SetDecimals(1);
  return map.ToSvg(900, 120 + 60 * static_cast<int>(methods.size()));
}

// The free-run figures of one held-out run: every method's, and (when asked) a subset's.
struct RunFigures {
  std::string all;    // "" when no method scored on the run
  std::string shown;  // the methods `shown` only; "" when none were asked for
};

// One held-out run (test maneuver `test`, first noise level and seed) against every method
// trained on the first training maneuver each could fit; each model free-run once for both
// figures, and each method in the same colour in both.
RunFigures ExampleRun(const Suite& suite, const std::vector<ResultRow>& rows,
                      const std::string& vessel, const std::string& test,
                      const std::set<std::string>& shown) {
  std::map<std::string, const ResultRow*> chosen;  // method -> row
  for (const ResultRow& r : rows)
    if (r.vessel == vessel && r.test_maneuver == test && r.status == "ok" &&
        ReportDrawsFreeRun(suite, r) && !chosen.count(r.method))
      chosen[r.method] = &r;
  if (chosen.empty()) return {};
  const ResultRow& first = *chosen.begin()->second;
  Dataset held;
  if (suite.Measured()) {
    for (const SuiteData& d : suite.test_data)
      if (d.name == test) held = LoadSuiteData(d);
  } else {
    held = SimulateForSuite(vessel, test, suite.test_seconds, first.noise, first.test_seed,
                            suite.conditions);
  }
  // The free run each row was scored on, or (a row read back from a resumed run's cells) the
  // same run again.
  std::map<std::string, std::shared_ptr<const FreeRun>> runs;
  for (const auto& [method, r] : chosen)
    runs[method] = r->free_run
                       ? r->free_run
                       : std::make_shared<const FreeRun>(
                             EvaluateModel(r->model, held, EvaluationScope::kFreeRunOnly).run);
  // The states the models identify (a vessel model: its dynamic states), and on measured data
  // the heading too.
  // Each method keeps its colour in every panel and both figures, also where another method has
  // no such channel.
  std::map<std::string, SeriesStyle> styles;
  for (const auto& [method, run] : runs)
    styles[method] = PaletteStyle(SeriesStyle::Dashed(), styles.size());
  const auto figure = [&](const std::set<std::string>& only) {
    std::set<std::string> channels;
    for (const auto& [method, run] : runs)
      if (only.empty() || only.contains(method))
        for (const std::string& c : run->channels)
          if (!IsPositionOrHeading(c) || (suite.Measured() && (c == "psi" || c == "chi")))
            channels.insert(c);
    FigureGrid grid;
    grid.SetTitle(VesselLabel(vessel) + ", held-out " + test + ": measured and free runs")
        .SetXLabel("t", "s");
    for (const std::string& c : channels) {
      if (!held.Has(c)) continue;
      LinePlot p;
      p.SetYLabel(c).AddSeries("measured", held.t(), held[c], SeriesStyle::Measured());
      for (const auto& [method, run] : runs)
        if ((only.empty() || only.contains(method)) && run->simulated.Has(c))
          p.AddSeries(method + " (trained on " + chosen[method]->train_maneuver + ")" +
                          (run->diverged ? ", diverged" : ""),
                      held.t(), run->simulated[c], styles.at(method));
      grid.Add(std::move(p));
    }
    return grid.ToSvg(1000, 80 + 240 * static_cast<int>(channels.size()));
  };
  return {figure({}), shown.empty() ? "" : figure(shown)};
}

// What a figure shows by default, so that it stays readable: nominal, then the `n` methods with
// the best median free-run fit over the vessel's rows (those with a finite one).
std::vector<std::string> ShownMethods(const std::vector<ResultRow>& rows, const std::string& vessel,
                                      size_t n) {
  std::map<std::string, std::vector<double>> fits;
  bool nominal = false;
  for (const ResultRow& r : rows) {
    if (r.vessel != vessel || r.status != "ok") continue;
    nominal = nominal || r.method == kNominalMethodName;
    if (std::isfinite(r.mean_fit_percent)) fits[r.method].push_back(r.mean_fit_percent);
  }
  std::vector<std::pair<double, std::string>> ranked;
  for (const auto& [method, f] : fits)
    if (method != kNominalMethodName) ranked.emplace_back(-Median(f), method);
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> shown;
  if (nominal) shown.emplace_back(kNominalMethodName);
  for (size_t i = 0; i < std::min(n, ranked.size()); ++i) shown.push_back(ranked[i].second);
  return shown;
}

// The plan views of a measured test that holds a zig-zag or a turning circle (harness/plan_view.h):
// the record and the methods `shown` (ShownMethods), each replayed as trained on the first
// training data it fitted.
std::vector<std::string> TestPlanViews(const Suite& suite, const std::vector<ResultRow>& rows,
                                       const std::string& vessel, const std::string& test,
                                       const std::vector<std::string>& shown) {
  const SuiteData* data = nullptr;
  for (const SuiteData& d : suite.test_data)
    if (d.name == test) data = &d;
  if (data == nullptr || data->maneuver.empty()) return {};
  std::map<std::string, const ResultRow*> model;  // method -> its row on this test
  for (const ResultRow& r : rows)
    if (r.vessel == vessel && r.status == "ok" && r.test_maneuver == test &&
        !model.count(r.method) && !r.model.is_null())
      model[r.method] = &r;
  std::vector<PlannedModel> drawn;
  for (const std::string& method : shown)
    if (model.count(method))
      drawn.push_back({method, model.at(method)->model, model.at(method)->replay});
  const Dataset held = LoadSuiteData(*data);
  const std::string spec = RecordedManeuverSpec(data->maneuver, vessel, held);
  return PlanView(VesselLabel(vessel) + ", held-out " + test, vessel, spec, held, drawn);
}

// A vessel's part of a figure's file name: a vessel file's stem (docs/vessels/files/esso-osaka.yaml
// -> esso-osaka), else the name.
std::string FigureName(const std::string& vessel) {
  std::string name = IsVesselFile(vessel) ? std::filesystem::path(vessel).stem().string() : vessel;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return name;
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
         "font-size:13px}th{border:1px solid #ccc;padding:3px "
         "8px;font-size:13px;background:#f3f3f3}"
         "figure{margin:1.5em 0}</style></head><body>\n";
  html << "<h1>usvid compare: " << svg::Escape(suite.name) << "</h1>\n";
  // The verdict opens the report, as it opens summary.md; the rest of the summary follows the
  // plots.
  const size_t rest = summary.find("\n## ", summary.find("## Verdict") + 1);
  html << MarkdownToHtml(summary.substr(0, rest));
  for (const std::string& vessel : vessels) {
    const std::string heat = FitHeatMap(suite, rows, vessel);
    WriteFileAtomically(dir + "/fit_" + FigureName(vessel) + ".svg", heat);
    html << "<h2>" << svg::Escape(VesselLabel(vessel)) << "</h2>\n<figure class=\"plot\">" << heat
         << "</figure>\n";
    // Simulated suites: the first test maneuver; measured data: every test file.
    const size_t tests = suite.Measured() ? suite.test_maneuvers.size() : 1;
    // Many methods on one figure are unreadable: nominal and the best three, every method a
    // click away (an HTML <details>, no script).
    const std::vector<std::string> shown = ShownMethods(rows, vessel, 3);
    std::set<std::string> methods;
    for (const ResultRow& r : rows)
      if (r.vessel == vessel) methods.insert(r.method);
    const std::set<std::string> subset = methods.size() <= shown.size()
                                             ? std::set<std::string>{}
                                             : std::set<std::string>(shown.begin(), shown.end());
    // Each test's figures replay every model on it: drawn side by side (each a pure function of
    // the rows, so the threads do not change them), written in order.
    std::vector<RunFigures> runs(tests);
    std::vector<std::vector<std::string>> plan_views(tests);
    std::vector<std::exception_ptr> errors(tests);
    ParallelFor(static_cast<int>(tests), omp_get_max_threads(), [&](int t) {
      try {
        runs[t] = ExampleRun(suite, rows, vessel, suite.test_maneuvers[t], subset);
        if (suite.Measured() && !runs[t].all.empty())
          plan_views[t] = TestPlanViews(suite, rows, vessel, suite.test_maneuvers[t], shown);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
    for (size_t t = 0; t < tests; ++t) {
      const RunFigures& run = runs[t];
      if (run.all.empty()) continue;
      WriteFileAtomically(
          dir + "/run_" + FigureName(vessel) + (t == 0 ? "" : "_" + std::to_string(t + 1)) + ".svg",
          run.all);
      if (run.shown.empty()) {
        html << "<figure class=\"plot\">" << run.all << "</figure>\n";
      } else {
        html << "<figure class=\"plot\">" << run.shown
             << "</figure>\n<details><summary>every method (" << methods.size()
             << ")</summary><figure class=\"plot\">" << run.all << "</figure></details>\n";
      }
      const std::vector<std::string>& plans = plan_views[t];
      for (size_t p = 0; p < plans.size(); ++p) {
        WriteFileAtomically(dir + "/plan_" + FigureName(vessel) + "_" + std::to_string(t + 1) +
                                (p == 0 ? "" : "_heading") + ".svg",
                            plans[p]);
        html << "<figure class=\"plot\">" << plans[p] << "</figure>\n";
      }
    }
  }
  if (rest != std::string::npos) html << MarkdownToHtml(summary.substr(rest));
  html << "</body></html>\n";
  WriteFileAtomically(dir + "/report.html", html.str());
}

}  // namespace usvid
