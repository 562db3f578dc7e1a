#include "harness/plan_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "core/error.h"
#include "maneuvers/maneuver_spec.h"
#include "metrics/closed_loop_replay.h"
#include "plot/figure_grid.h"
#include "plot/svg_plot.h"

namespace usvid {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct Track {
  std::string label;
  Dataset run;
  bool diverged = false;  // drawn, clipped, but not setting the scale
};

// The track's heading turned from its first row [deg], unwrapped.
Eigen::VectorXd TurnedDeg(const Dataset& run) {
  const Eigen::VectorXd psi = UnwrappedAngle(run["psi"]);
  return (psi.array() - psi(0)) * kDeg;
}

// The first row at which the track has turned `deg` either way, or -1.
Eigen::Index FirstTurned(const Eigen::VectorXd& turned, double deg) {
  for (Eigen::Index k = 0; k < turned.size(); ++k)
    if (std::abs(turned(k)) >= deg) return k;
  return -1;
}

// North against east from each track's first position, on one scale (set by the tracks that did
// not diverge), the turning marks added.
std::string Plan(const std::string& title, const std::vector<Track>& tracks, bool turning) {
  LinePlot plot;
  plot.SetTitle(title + ": plan from the execute's lead-in")
      .SetXLabel("east", "m")
      .SetYLabel("north", "m")
      .SetLegendPlacement(LegendPlacement::kBelow);
  double lo_e = 0, hi_e = 0, lo_n = 0, hi_n = 0;
  std::vector<double> mark_e[2], mark_n[2];
  for (size_t i = 0; i < tracks.size(); ++i) {
    const Dataset& run = tracks[i].run;
    const Eigen::VectorXd e = run["east"].array() - run["east"](0);
    const Eigen::VectorXd n = run["north"].array() - run["north"](0);
    if (!tracks[i].diverged && e.allFinite() && n.allFinite()) {
      lo_e = std::min(lo_e, e.minCoeff()), hi_e = std::max(hi_e, e.maxCoeff());
      lo_n = std::min(lo_n, n.minCoeff()), hi_n = std::max(hi_n, n.maxCoeff());
    }
    plot.AddSeries(tracks[i].label, e, n,
                   i == 0 ? SeriesStyle::Measured() : PaletteStyle(SeriesStyle::Dashed(), i - 1));
    if (!turning || !run.Has("psi")) continue;
    const Eigen::VectorXd turned = TurnedDeg(run);
    for (int m = 0; m < 2; ++m) {
      const Eigen::Index k = FirstTurned(turned, m == 0 ? 90.0 : 180.0);
      if (k < 0) continue;
      mark_e[m].push_back(e(k));
      mark_n[m].push_back(n(k));
    }
  }
  if (turning) {
    SeriesStyle mark = SeriesStyle::Markers();
    mark.marker_radius = 5.0;
    mark.color = "#222";
    plot.AddSeries("turned 90 deg: the advance", mark_e[0], mark_n[0], mark);
    mark.color = "#c00";
    plot.AddSeries("turned 180 deg: the tactical diameter", mark_e[1], mark_n[1], mark);
  }
  // One scale on both axes: a circle looks round.
  const double span = 1.1 * std::max({hi_e - lo_e, hi_n - lo_n, 1.0});
  const double ce = 0.5 * (lo_e + hi_e), cn = 0.5 * (lo_n + hi_n);
  plot.SetXRange(ce - span / 2, ce + span / 2).SetYRange(cn - span / 2, cn + span / 2);
  return plot.ToSvg(760, 860);
}

// Heading from the first row and rudder against time, the band +-B about the base course.
std::string HeadingAndRudder(const std::string& title, const std::vector<Track>& tracks,
                             const std::string& rudder, double base_deg, double check_deg) {
  FigureGrid grid;
  grid.SetTitle(title + ": heading and rudder").SetXLabel("t", "s");
  LinePlot heading, helm;
  heading.SetYLabel("heading turned", "deg");
  // The checks +-B about the base course, across the record: the overshoots lie beyond.
  const Eigen::VectorXd& t = tracks.front().run.t();
  const double nan = std::nan("");
  const std::vector<double> x = {t(0), t(t.size() - 1), nan, t(0), t(t.size() - 1)};
  const std::vector<double> y = {base_deg + check_deg, base_deg + check_deg, nan,
                                 base_deg - check_deg, base_deg - check_deg};
  SeriesStyle check = SeriesStyle::Dotted();
  check.color = "#444";
  check.line_width = 1.0;
  heading.AddSeries("base course +-" + std::to_string(static_cast<int>(std::lround(check_deg))), x,
                    y, check);
  helm.SetYLabel(rudder, "deg");
  for (size_t i = 0; i < tracks.size(); ++i) {
    const Dataset& run = tracks[i].run;
    const SeriesStyle style =
        i == 0 ? SeriesStyle::Measured() : PaletteStyle(SeriesStyle::Dashed(), i - 1);
    if (run.Has("psi")) heading.AddSeries(tracks[i].label, run.t(), TurnedDeg(run), style);
    if (run.Has(rudder)) helm.AddSeries(tracks[i].label, run.t(), run[rudder] * kDeg, style);
  }
  grid.Add(std::move(heading), 1.6).Add(std::move(helm));
  return grid.ToSvg(1000, 620);
}

}  // namespace

std::vector<std::string> PlanView(const std::string& title, const std::string& vessel,
                                  const std::string& spec, const Dataset& held,
                                  const std::vector<PlannedModel>& models) {
  if (!IsManeuverTest(spec) || !held.Has("north") || !held.Has("east") || !held.Has("psi"))
    return {};
  try {
    const ManeuverScorer scorer(vessel, spec, held);
    std::vector<Track> tracks = {{"measured", scorer.recorded()}};
    for (const auto& [label, model, scored] : models) {
      try {
        const std::shared_ptr<const ClosedLoopReplay> replay =
            scored ? scored : std::make_shared<const ClosedLoopReplay>(scorer.Replay(model));
        if (!replay->run.Has("north") || !replay->run.Has("east")) continue;
        tracks.push_back(
            {label + (replay->diverged ? ", diverged" : ""), replay->run, replay->diverged});
      } catch (const InputError&) {
        // Not replayable (an open-loop model of other inputs): its row says why.
      }
    }
    const ManeuverSpec parsed = ParseManeuverSpec(spec);
    const bool zigzag = parsed.kind == ManeuverKind::kZigzag;
    std::vector<std::string> figures = {Plan(title, tracks, !zigzag)};
    if (zigzag)
      figures.push_back(HeadingAndRudder(title, tracks, scorer.rudder(),
                                         scorer.base_course_offset_rad() * kDeg,
                                         parsed.CheckDeg()));
    return figures;
  } catch (const InputError&) {
    return {};  // the record does not hold the maneuver as read: no plan to draw
  }
}

}  // namespace usvid
