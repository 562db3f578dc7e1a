#include "diagnosis/diagnosis_report.h"

#include <iomanip>
#include <sstream>

#include "core/atomic_file.h"
#include "methods/nominal/nominal.h"
#include "plot/figure_grid.h"
#include "plot/svg_text.h"

namespace usvid::diagnosis {
namespace {

std::string Fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string Sizes(const Effect& e) {
  std::string out;
  for (const auto& [name, value] : e.parameters)
    out += (out.empty() ? "" : ", ") + name + " = " + Fixed(value, 4);
  for (size_t i = 0; i < e.inputs.size(); ++i) out += (i ? "+" : ", on ") + e.inputs[i];
  if (e.kind == EffectKind::kMissingTerm) out += " x " + e.term + " in " + e.state + "'";
  return out;
}

std::string FitCells(const FitPercent& fit, const std::vector<std::string>& channels) {
  std::string out;
  for (const std::string& c : channels) {
    const auto it = fit.find(c);
    out += "<td>" + (it != fit.end() ? Fixed(it->second, 1) : std::string("-")) + "</td>";
  }
  return out;
}

std::string HeldoutFigure(const Diagnosis& d) {
  // Every cause the extended model has.
  std::string causes = d.cause_effect ? EffectLabel(*d.cause_effect) : d.cause;
  for (const FurtherCause& f : d.further_causes) causes += " + " + EffectLabel(f.effect);
  FigureGrid grid;
  grid.SetTitle("held-out part: measured, nominal and extended (" + causes +
                "), each segment from its estimated initial state")
      .SetXLabel("t", "s");
  for (const std::string& c : d.channels) {
    LinePlot p;
    p.SetYLabel(c)
        .AddSeries("measured", d.series.t, d.series.measured.at(c), SeriesStyle::Measured())
        .AddSeries(std::string(kNominalMethodName), d.series.t, d.series.nominal.at(c));
    if (d.cause_effect) p.AddSeries("extended", d.series.t, d.series.extended.at(c));
    grid.Add(std::move(p));
  }
  return grid.ToSvg(1000, 200 * static_cast<int>(d.channels.size()) + 80);
}

}  // namespace

void WriteDiagnosisReport(const Diagnosis& d, const std::string& dir) {
  const std::string figure = HeldoutFigure(d);
  WriteFileAtomically(dir + "/heldout.svg", figure);
  std::ostringstream h;
  h << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>usvid diagnose: "
    << svg::Escape(d.vessel)
    << "</title>\n<style>body{font-family:sans-serif;max-width:1060px;"
       "margin:2em auto;color:#222}table{border-collapse:collapse;margin:1em 0}td,th{border:1px "
       "solid #ccc;padding:3px 8px;font-size:13px}tr.cause{background:#e6f4e6}</style></head>"
       "<body>\n";
  h << "<h1>usvid diagnose: " << svg::Escape(d.vessel) << " on " << svg::Escape(d.source)
    << "</h1>\n";
  h << "<p><b>Cause: " << svg::Escape(d.cause_effect ? EffectLabel(*d.cause_effect) : d.cause)
    << "</b>";
  if (d.cause_effect) h << " (" << svg::Escape(Sizes(*d.cause_effect)) << ")";
  for (const FurtherCause& f : d.further_causes)
    h << "; then, on the model extended so far, <b>" << svg::Escape(EffectLabel(f.effect))
      << "</b> (" << svg::Escape(Sizes(f.effect)) << ", LR " << Fixed(f.likelihood_ratio, 1) << ")";
  if (!d.base_effects.empty()) {
    h << "; the nominal model already had";
    for (const Effect& e : d.base_effects)
      h << " " << svg::Escape(EffectLabel(e)) << " (" << svg::Escape(Sizes(e)) << ")";
  }
  h << ". Held-out error reduction " << Fixed(100.0 * d.heldout_error_reduction, 1)
    << " %. Trained on the first " << Fixed(d.train_s, 0) << " s"
    << (d.fit_s < d.train_s - 1e-9 ? " (the effects fitted on its last " + Fixed(d.fit_s, 0) + " s)"
                                   : std::string())
    << ", scored on the " << Fixed(d.heldout_s, 0) << " s that follow, in segments of "
    << Fixed(d.segment_s, 0)
    << " s, each from an initial state estimated from the data. Noise floor E = "
    << std::setprecision(3) << d.noise_floor << ", nominal E = " << d.nominal_error << ".</p>\n";

  h << "<h2>Held-out fit %</h2>\n<table><tr><th>model</th>";
  for (const std::string& c : d.channels) h << "<th>" << svg::Escape(c) << "</th>";
  h << "</tr>\n<tr><td>nominal</td>" << FitCells(d.nominal_fit_percent, d.channels) << "</tr>\n";
  h << "<tr><td>extended</td>" << FitCells(d.extended_fit_percent, d.channels) << "</tr>\n";
  h << "<tr><td>nominal, free run (all data)</td>"
    << FitCells(d.nominal_free_run_fit_percent, d.channels) << "</tr></table>\n";
  h << "<figure>" << figure << "</figure>\n";

  h << "<h2>Candidates, best first</h2>\n<table><tr><th>effect</th><th>fitted sizes</th>";
  for (const std::string& c : d.channels) h << "<th>" << svg::Escape(c) << " %</th>";
  h << "<th>held-out E</th><th>explained</th><th>score (AIC)</th></tr>\n";
  for (const Candidate& c : d.candidates) {
    const bool cause = d.cause_effect && SameEffect(c.fit.effect, *d.cause_effect);
    h << "<tr" << (cause ? " class=\"cause\"" : "") << "><td>"
      << svg::Escape(EffectLabel(c.fit.effect)) << "</td><td>" << svg::Escape(Sizes(c.fit.effect))
      << "</td>" << FitCells(c.heldout_fit_percent, d.channels) << "<td>" << std::setprecision(4)
      << c.heldout_error << "</td><td>" << Fixed(100.0 * c.explained, 1) << " %</td><td>"
      << Fixed(c.score, 1) << "</td></tr>\n";
  }
  h << "</table>\n";

  h << "<h2>What the nominal simulation gets wrong</h2>\n<p>Residual e = measured - nominal "
       "(segment-reset run over all data): mean (bias), mean slope within segments (drift), how "
       "late the measured channel follows the model (lag), and the strongest correlations.</p>\n"
       "<table><tr><th>channel</th><th>free-run fit %</th><th>bias</th><th>drift /s</th>"
       "<th>lag s</th><th>input correlation (lag s)</th><th>regressor correlation</th></tr>\n";
  for (const ChannelResidual& r : d.residuals) {
    std::string inputs, regressors;
    for (const InputCorrelation& c : r.inputs)
      inputs += c.input + " " + Fixed(c.correlation, 2) + " (" + Fixed(c.lag_s, 2) + ")<br>";
    for (const auto& [name, value] : r.regressors)
      regressors += name + " " + Fixed(value, 2) + "<br>";
    h << "<tr><td>" << svg::Escape(r.channel) << "</td><td>" << Fixed(r.free_run_fit_percent, 1)
      << "</td><td>" << std::setprecision(4) << r.bias << "</td><td>" << r.drift_per_s
      << "</td><td>" << Fixed(r.lag_s, 2) << "</td><td>" << inputs << "</td><td>" << regressors
      << "</td></tr>\n";
  }
  h << "</table>\n";
  if (!d.discovered.empty()) {
    h << "<h2>Beyond the catalogue: terms the nominal model lacks</h2>\n<table><tr><th>state"
         "</th><th>missing part of its derivative</th><th>held-out R&sup2;</th><th>by</th></tr>\n";
    for (const DiscoveredTerms& t : d.discovered)
      h << "<tr><td>" << svg::Escape(t.state) << "</td><td><code>" << svg::Escape(t.expression)
        << "</code></td><td>" << Fixed(t.heldout_r2, 3) << "</td><td>" << t.method
        << "</td></tr>\n";
    h << "</table>\n";
  }
  h << "</body></html>\n";
  WriteFileAtomically(dir + "/report.html", h.str());
}

}  // namespace usvid::diagnosis
