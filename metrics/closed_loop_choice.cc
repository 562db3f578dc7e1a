#include "metrics/closed_loop_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "core/model_view.h"
#include "maneuvers/maneuver_spec.h"
#include "metrics/recorded_tests.h"
#include "metrics/zigzag_response.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// The training records' zig-zags and turning circles. A zig-zag judges a model where its
// reversals show it: a half swing at least, which the reading checks against the first order
// (zigzag_response.h); with one reversal alone nothing tells a random run's reversal from full
// angle from a zig-zag's.
std::vector<RecordedTest> TestRecords(const Dataset& train, const VesselRef& vessel) {
  std::vector<RecordedTest> out;
  for (RecordedTest& t : RecordedTests(train, vessel, {"zigzag", "turning"}))
    if (KindOfManeuver(t.spec) != ManeuverKind::kZigzag ||
        ReadZigzagCheck(t.scorer.recorded(), "psi", t.scorer.rudder()).half_swings >= 1)
      out.push_back(std::move(t));
  return out;
}

struct Criteria {
  double first_overshoot_deg = kNone;        // mean |error| over the zig-zags
  double tactical_diameter_percent = kNone;  // mean |error| over the circles, of the measured
  std::string status;                        // the first replay that was not ok, else ""
};

Criteria Replay(const nlohmann::json& model, const std::vector<RecordedTest>& tests) {
  Criteria c;
  double overshoot = 0.0, diameter = 0.0;
  int zigzags = 0, circles = 0;
  for (const RecordedTest& t : tests) {
    const nlohmann::json score = t.scorer.Score(model);
    if (score.value("status", std::string()) != "ok") {
      c.status = t.spec + ": " + score.value("status", std::string("no status"));
      return c;
    }
    if (score.contains("first_overshoot_error_deg") &&
        score["first_overshoot_error_deg"].is_number()) {
      overshoot += std::abs(score["first_overshoot_error_deg"].get<double>());
      ++zigzags;
    }
    const nlohmann::json measured = score.value("measured", nlohmann::json::object());
    if (score.contains("tactical_diameter_error_m") &&
        score["tactical_diameter_error_m"].is_number() &&
        measured.value("tactical_diameter_m", 0.0) > 0.0) {
      diameter += 100.0 * std::abs(score["tactical_diameter_error_m"].get<double>()) /
                  measured["tactical_diameter_m"].get<double>();
      ++circles;
    }
  }
  if (zigzags > 0) c.first_overshoot_deg = overshoot / zigzags;
  if (circles > 0) c.tactical_diameter_percent = diameter / circles;
  return c;
}

// Whether `c` is no worse than `base` on each criterion `base` has (a base that could not be
// replayed bars nothing that could).
bool NoWorse(const Criteria& c, const Criteria& base) {
  if (!c.status.empty()) return false;
  if (!base.status.empty()) return true;
  const auto ok = [](double x, double limit) { return std::isnan(limit) || x <= limit; };
  return ok(c.first_overshoot_deg, base.first_overshoot_deg) &&
         ok(c.tactical_diameter_percent, base.tactical_diameter_percent);
}

nlohmann::json OrNull(double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); }

// An alternative's replayed criteria, as its row of the report.
nlohmann::json CriteriaRow(const Criteria& c, bool admissible) {
  nlohmann::json row{{"first_overshoot_error_deg", OrNull(c.first_overshoot_deg)},
                     {"tactical_diameter_error_percent", OrNull(c.tactical_diameter_percent)},
                     {"admissible", admissible}};
  if (!c.status.empty()) row["status"] = c.status;
  return row;
}

}  // namespace

nlohmann::json ChooseByClosedLoop(nlohmann::json& model, const Dataset& train,
                                  const VesselRef& vessel_given) {
  nlohmann::json report = {{"applied", false}};
  const VesselRef vessel =
      !vessel_given.empty() ? vessel_given : VesselRef(ModelView(model).Vessel());
  const std::vector<ModelAlternative> alternatives = ModelView(model).Alternatives();
  if (alternatives.empty()) {
    report["reason"] = "the model weighed no alternatives";
    return report;
  }
  if (vessel.empty()) {
    report["reason"] = "no vessel to take the replay's rudder from";
    return report;
  }
  // A zig-zag's and a turning circle's angles are a rudder's: odin3dof steers by a yaw moment.
  if (!vessel.Info().actuation.yaw_is_angle) {
    report["reason"] =
        "the vessel steers by no rudder angle, so no zig-zag or turning circle is "
        "read from the records: the free runs chose";
    return report;
  }
  const std::vector<RecordedTest> tests = TestRecords(train, vessel);
  if (tests.empty()) {
    report["reason"] =
        "no zig-zag or turning circle among the training records: the free runs chose";
    return report;
  }
  for (const RecordedTest& t : tests) report["maneuvers"].push_back(t.spec);
  // The lowest free-run error among the admissible: the alternatives are replayed in the order
  // of their free-run errors, and the first admissible one is chosen; alternatives[0] is the
  // vessel as given (methods/gp/grey_box.h), admissible by definition, so none with a higher
  // error than the vessel's is replayed.
  const auto free_run = [&](size_t i) { return alternatives[i].FreeRunError(); };
  std::vector<size_t> order(alternatives.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return free_run(a) < free_run(b); });
  nlohmann::json trial = model;
  ModelEdit(trial).SetEffects(alternatives[0].effects);
  const Criteria as_given = Replay(trial, tests);
  size_t chosen = 0;
  std::map<size_t, nlohmann::json> rows;
  for (const size_t i : order) {
    if (i == 0 || !(free_run(i) < free_run(0))) break;
    ModelEdit(trial).SetEffects(alternatives[i].effects);
    const Criteria c = Replay(trial, tests);
    const bool admissible = NoWorse(c, as_given);
    rows[i] = CriteriaRow(c, admissible);
    if (admissible) {
      chosen = i;
      break;
    }
  }
  rows[0] = CriteriaRow(as_given, true);
  for (size_t i = 0; i < alternatives.size(); ++i) {
    nlohmann::json row = {{"label", alternatives[i].label},
                          {"free_run_error", alternatives[i].free_run_error}};
    if (rows.contains(i))
      row.update(rows[i]);
    else
      row["replayed"] = false;  // its free runs were no better than the choice's or the vessel's
    report["alternatives"].push_back(row);
  }
  const ModelAlternative& best = alternatives[chosen];
  ModelEdit edit(model);
  edit.SetEffects(best.effects);
  edit.SetCorrections(best.corrections);
  report["applied"] = true;
  report["chosen"] = best.label;
  report["reason"] =
      "the lowest held-out free-run error among the models whose training zig-zags and turning "
      "circles, replayed closed-loop, are no worse than the vessel's";
  return report;
}

}  // namespace usvid
