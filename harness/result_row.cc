#include "harness/result_row.h"

namespace usvid {

nlohmann::json ResultRow::ToJson() const {
  nlohmann::json j = {{"vessel", vessel},
                      {"train_maneuver", train_maneuver},
                      {"test_maneuver", test_maneuver},
                      {"method", method},
                      {"inputs", inputs},
                      {"noise", noise},
                      {"seed", seed},
                      {"test_seed", test_seed},
                      {"status", status}};
  if (status == "ok") {
    j["fit_percent"] = fit_percent;
    j["channel_fit_percent"] = channel_fit_percent;
    j["nrmse"] = nrmse;
    j["mean_fit_percent"] = mean_fit_percent;
    j["diverged"] = diverged;
    if (diverged) {
      j["diverged_at_s"] = diverged_at_s;
      j["diverged_channel"] = diverged_channel;
    }
    j["horizon_fit_percent"] = horizon_fit_percent;
    if (valid_prediction_s) j["valid_prediction_s"] = *valid_prediction_s;
    if (!derivative_r2.empty()) j["derivative_r2"] = derivative_r2;
    j["fit_seconds"] = fit_seconds;
    j["terms"] = terms;
    if (!regime_fit_percent.empty()) j["regime_fit_percent"] = regime_fit_percent;
    if (precision) j["structure_precision"] = *precision;
    if (recall) j["structure_recall"] = *recall;
    if (parameter_error) j["parameter_error"] = *parameter_error;
  }
  // Every row says whether its test was replayed closed-loop, failed fits too.
  if (!closed_loop.is_null()) j["closed_loop"] = closed_loop;
  return j;
}

nlohmann::json ResultRow::ToCellJson() const {
  nlohmann::json j = ToJson();
  j["fit_seconds"] = fit_seconds;
  return j;
}

ResultRow ResultRow::FromCellJson(const nlohmann::json& j) {
  ResultRow r;
  r.vessel = j.at("vessel").get<std::string>();
  r.train_maneuver = j.at("train_maneuver").get<std::string>();
  r.test_maneuver = j.at("test_maneuver").get<std::string>();
  r.method = j.at("method").get<std::string>();
  r.inputs = j.value("inputs", "");
  r.noise = j.at("noise").get<double>();
  r.seed = j.at("seed").get<uint64_t>();
  r.test_seed = j.at("test_seed").get<uint64_t>();
  r.status = j.at("status").get<std::string>();
  r.fit_seconds = j.at("fit_seconds").get<double>();
  if (j.contains("closed_loop")) r.closed_loop = j["closed_loop"];
  if (r.status != "ok") return r;
  r.fit_percent = j.at("fit_percent").get<std::map<std::string, double>>();
  r.channel_fit_percent = j.at("channel_fit_percent").get<std::map<std::string, double>>();
  r.nrmse = j.at("nrmse").get<std::map<std::string, double>>();
  r.mean_fit_percent = j.at("mean_fit_percent").get<double>();
  r.diverged = j.at("diverged").get<bool>();
  r.diverged_at_s = j.value("diverged_at_s", 0.0);
  r.diverged_channel = j.value("diverged_channel", "");
  r.horizon_fit_percent = j.at("horizon_fit_percent").get<std::map<std::string, double>>();
  if (j.contains("valid_prediction_s"))
    r.valid_prediction_s = j["valid_prediction_s"].get<double>();
  if (j.contains("derivative_r2"))
    r.derivative_r2 = j["derivative_r2"].get<std::map<std::string, double>>();
  r.terms = j.at("terms").get<int>();
  if (j.contains("regime_fit_percent"))
    r.regime_fit_percent = j["regime_fit_percent"].get<std::map<std::string, double>>();
  if (j.contains("structure_precision")) r.precision = j["structure_precision"].get<double>();
  if (j.contains("structure_recall")) r.recall = j["structure_recall"].get<double>();
  if (j.contains("parameter_error")) r.parameter_error = j["parameter_error"].get<double>();
  return r;
}

}  // namespace usvid
