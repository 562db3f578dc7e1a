#include "harness/regression.h"

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.h"

namespace usvid {
namespace {

using Key = std::tuple<std::string, std::string, std::string, std::string, double>;

struct Samples {
  std::vector<double> fit, seconds;
};

std::pair<double, double> MeanSd(const std::vector<double>& v) {
  double mean = 0.0, var = 0.0;
  for (double x : v) mean += x / static_cast<double>(v.size());
  for (double x : v) var += (x - mean) * (x - mean) / std::max<double>(1.0, v.size() - 1.0);
  return {mean, std::sqrt(var)};
}

}  // namespace

std::string RegressionReport::Markdown() const {
  std::ostringstream md;
  md << "## Against the baseline\n\n"
     << worse << " of " << groups.size() << " groups got worse beyond the spread over seeds.\n\n";
  for (const auto& g : groups)
    if (g.at("verdict") != "same")
      md << "- " << g.at("vessel").get<std::string>() << " / "
         << g.at("train_maneuver").get<std::string>() << " -> "
         << g.at("test_maneuver").get<std::string>() << " / " << g.at("method").get<std::string>()
         << " / noise " << g.at("noise").get<double>() << ": " << g.at("verdict").get<std::string>()
         << '\n';
  return md.str();
}

RegressionReport CompareWithBaseline(const std::vector<ResultRow>& rows,
                                     const nlohmann::json& baseline, const std::string& file) {
  if (!baseline.is_object() || !baseline.contains("rows") || !baseline["rows"].is_array())
    throw InputError(file + ": not a results.json (no \"rows\" array)");
  std::map<Key, Samples> now, before;
  for (const ResultRow& r : rows)
    if (r.status == "ok") {
      Samples& s = now[{r.vessel, r.train_maneuver, r.test_maneuver, r.method, r.noise}];
      s.fit.push_back(r.mean_fit_percent);
      s.seconds.push_back(r.fit_seconds);
    }
  for (const auto& r : baseline["rows"]) {
    try {
      if (r.at("status") != "ok") continue;
      Samples& s = before[{r.at("vessel"), r.at("train_maneuver"), r.at("test_maneuver"),
                           r.at("method"), r.at("noise")}];
      s.fit.push_back(r.at("mean_fit_percent").get<double>());
      s.seconds.push_back(r.at("fit_seconds").get<double>());
    } catch (const nlohmann::json::exception& e) {
      throw InputError(file + ": a row lacks a field or has the wrong type (" + e.what() + ")");
    }
  }
  RegressionReport report;
  for (const auto& [key, cur] : now) {
    const auto& [vessel, train, test, method, noise] = key;
    nlohmann::json g = {{"vessel", vessel},
                        {"train_maneuver", train},
                        {"test_maneuver", test},
                        {"method", method},
                        {"noise", noise}};
    const auto it = before.find(key);
    if (it == before.end()) {
      g["verdict"] = "new (not in the baseline)";
      report.groups.push_back(g);
      continue;
    }
    const auto [fit_now, fit_sd_now] = MeanSd(cur.fit);
    const auto [fit_then, fit_sd_then] = MeanSd(it->second.fit);
    const auto [t_now, t_sd_now] = MeanSd(cur.seconds);
    const auto [t_then, t_sd_then] = MeanSd(it->second.seconds);
    const double spread = std::max({fit_sd_now, fit_sd_then, 0.5});
    const double t_spread = std::max({t_sd_now, t_sd_then, 0.01});
    std::string verdict = "same";
    if (fit_now < fit_then - spread) {
      verdict = "worse fit";
    } else if (t_now > 1.5 * t_then && t_now > t_then + 3 * t_spread) {
      verdict = "slower";
    }
    if (verdict != "same") ++report.worse;
    g.update({{"fit_percent", fit_now},
              {"baseline_fit_percent", fit_then},
              {"spread", spread},
              {"fit_seconds", t_now},
              {"baseline_fit_seconds", t_then},
              {"verdict", verdict}});
    report.groups.push_back(g);
  }
  return report;
}

}  // namespace usvid
