#include "metrics/yaw_bias_calibration.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/derived_channels.h"
#include "core/expression.h"
#include "core/model_view.h"
#include "core/parse_number.h"
#include "metrics/closed_loop_choice.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/recorded_tests.h"

namespace usvid {
namespace {

constexpr int kScanSteps = 10;      // each side of 0: 21 points
constexpr double kScanShare = 0.5;  // of the r equation's spread over the training rows
constexpr int kGoldenIterations = 14;

// An equation as its leading constant and the rest: "c - w*x" is (c, " - w*x"); an equation
// that does not begin with a number is (0, " + (equation)").
struct ConstantAndRest {
  double constant = 0.0;
  std::string rest;
};

ConstantAndRest SplitConstant(const std::string& equation) {
  const size_t space = equation.find(' ');
  const std::string head = equation.substr(0, space);
  const ParsedNumber n = ParseNumber(head);
  const std::string tail = space == std::string::npos ? "" : equation.substr(space);
  if (n.status == NumberStatus::kOk &&
      (tail.empty() || tail.starts_with(" + ") || tail.starts_with(" - ")))
    return {n.value, tail};
  return {0.0, " + (" + equation + ")"};
}

// The spread (standard deviation) of the r equation over the rows where it is defined.
double EquationSpread(const std::string& equation, const Dataset& train) {
  Dataset data = train;
  AddDerivedChannels(data);
  const Eigen::VectorXd value = Expression::Parse(equation, "equation of r").Evaluate(data);
  double sum = 0.0, sum2 = 0.0;
  long n = 0;
  for (double x : value)
    if (std::isfinite(x)) {
      sum += x;
      sum2 += x * x;
      ++n;
    }
  if (n < 2) return 0.0;
  const double mean = sum / static_cast<double>(n);
  return std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
}

struct CriteriaCost {
  double cost = std::numeric_limits<double>::infinity();
  std::vector<double> errors;  // each zig-zag's first and second overshoot error
  std::string status;          // the first replay that was not ok
};

// The sum of the squared first and second overshoot errors of `model` replayed on every zig-zag;
// infinite, with the status, when a replay or a record gives no second overshoot.
CriteriaCost OvershootCost(const nlohmann::json& model, const std::vector<RecordedTest>& zigzags) {
  CriteriaCost e;
  double cost = 0.0;
  for (const RecordedTest& z : zigzags) {
    const nlohmann::json score = z.scorer.Score(model);
    const nlohmann::json& first = score["first_overshoot_error_deg"];
    const nlohmann::json& second = score["second_overshoot_error_deg"];
    if (score["status"] != "ok" || !first.is_number() || !second.is_number()) {
      e.status = z.spec + ": " +
                 (score["status"] != "ok" ? score["status"].get<std::string>()
                                          : "the replay or the record has no second overshoot");
      return e;
    }
    e.errors.push_back(first.get<double>());
    e.errors.push_back(second.get<double>());
    cost += first.get<double>() * first.get<double>() + second.get<double>() * second.get<double>();
  }
  e.cost = cost;
  return e;
}

// The shift of lowest cost: a scan of kScanSteps steps each side of 0, then golden-section search
// between the best point's neighbours. `best` holds the cost at 0 on entry, the shift's on return.
template <typename Evaluate>
double BestShift(const Evaluate& evaluate, double step, CriteriaCost& best) {
  double best_shift = 0.0;
  for (int k = -kScanSteps; k <= kScanSteps; ++k) {
    if (k == 0) continue;
    const CriteriaCost e = evaluate(k * step);
    if (e.cost < best.cost) {
      best = e;
      best_shift = k * step;
    }
  }
  if (!std::isfinite(best.cost)) return best_shift;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = best_shift - step, b = best_shift + step;
  double c = b - g * (b - a), d = a + g * (b - a);
  CriteriaCost fc = evaluate(c), fd = evaluate(d);
  for (int i = 0; i < kGoldenIterations; ++i) {
    if (fc.cost < fd.cost) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = evaluate(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = evaluate(d);
    }
  }
  for (const auto& [shift, e] : {std::pair{c, fc}, std::pair{d, fd}})
    if (e.cost < best.cost) {
      best = e;
      best_shift = shift;
    }
  return best_shift;
}

}  // namespace

nlohmann::json CalibrateYawBias(nlohmann::json& model, const Dataset& train,
                                const VesselRef& vessel_given) {
  nlohmann::json report = {{"applied", false}};
  const VesselRef vessel =
      !vessel_given.empty() ? vessel_given : VesselRef(ModelView(model).Vessel());
  const std::optional<std::string> equation = ModelView(model).Equation("r");
  if (!equation) {
    report["reason"] = "the model has no equation of r";
    return report;
  }
  if (vessel.empty()) {
    report["reason"] = "no vessel to take the replay's rudder from";
    return report;
  }
  const std::vector<RecordedTest> zigzags = RecordedTests(train, vessel, {"zigzag"});
  if (zigzags.empty()) {
    report["reason"] = "no zig-zag among the training records";
    return report;
  }
  for (const RecordedTest& z : zigzags) report["maneuvers"].push_back(z.spec);

  const ConstantAndRest split = SplitConstant(*equation);
  auto with_constant = [&](double c) { return FormatNumber(c) + split.rest; };
  nlohmann::json trial = model;
  auto evaluate = [&](double shift) {
    ModelEdit(trial).SetEquation("r", with_constant(split.constant + shift));
    return OvershootCost(trial, zigzags);
  };

  const CriteriaCost before = evaluate(0.0);
  report["constant_before"] = split.constant;
  report["overshoot_errors_before"] = before.errors;
  if (!before.status.empty()) report["status_before"] = before.status;
  const double step = kScanShare * EquationSpread(*equation, train) / kScanSteps;
  if (!(step > 0.0) || !std::isfinite(step)) {
    report["reason"] = "the r equation does not vary over the training rows";
    return report;
  }
  CriteriaCost best = before;
  const double best_shift = BestShift(evaluate, step, best);
  if (!(best.cost < before.cost)) {
    report["reason"] = std::isfinite(before.cost)
                           ? "no other constant gives the training zig-zags' overshoots closer"
                           : "no constant lets the model replay its training zig-zags";
    return report;
  }
  const double constant = split.constant + best_shift;
  ModelEdit edit(model);
  edit.SetEquation("r", with_constant(constant));
  edit.UpdateParameter("r.bias", constant);
  report["applied"] = true;
  report["reason"] =
      "the constant that gives the model the training zig-zags' overshoots, replayed closed-loop";
  report["shift"] = best_shift;
  report["constant_after"] = constant;
  report["overshoot_errors_after"] = best.errors;
  return report;
}

void CalibrateRequested(nlohmann::json& model, const Dataset& train, const VesselRef& vessel) {
  if (ModelView(model).Calibration("choose") == "closed-loop")
    ModelEdit(model).SetCalibration("choose", ChooseByClosedLoop(model, train, vessel));
  if (ModelView(model).Calibration("yaw_bias") != "zigzag") return;
  nlohmann::json report = CalibrateYawBias(model, train, vessel);
  ModelEdit(model).SetCalibration("yaw_bias", std::move(report));
}

}  // namespace usvid
