#include "harness/run_suite.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <numeric>
#include <set>
#include <tuple>

#include "core/error.h"
#include "core/model_view.h"
#include "core/parallel_for.h"
#include "core/records.h"
#include "effects/effect.h"
#include "harness/cross_validation.h"
#include "harness/fit_service.h"
#include "harness/suite_methods.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/maneuver_spec.h"
#include "methods/channel_fit.h"
#include "methods/refit/refit.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/evaluation.h"
#include "metrics/maneuver_of_record.h"
#include "metrics/structure.h"
#include "simulation/logged_disturbances.h"
#include "simulation/simulate_record.h"
#include "simulation/vessel_simulator.h"
#include "simulators/vessel.h"

namespace usvid {

Dataset SimulateForSuite(const VesselRef& vessel, const std::string& maneuver, double seconds,
                         double noise, uint64_t seed, const SuiteConditions& conditions) {
  RecordRecipe recipe;
  recipe.vessel = vessel;
  recipe.maneuver = maneuver;
  // A step grid runs until its grid is done.
  recipe.duration_s = KindOfManeuver(maneuver) == ManeuverKind::kStepGrid ? 0.0 : seconds;
  recipe.effects = ParseEffects(conditions.effects, seed);
  recipe.gusts = conditions.gusts;
  recipe.logged = conditions.logged;
  recipe.sensors = {conditions.waves, noise, conditions.sensors, conditions.dropouts};
  recipe.seed = seed;
  return SimulateRecord(recipe).data;
}

namespace {

// Complexity, structure recovery against the true terms, and parameter error against the
// simulator's parameters where the model names them.
void ScoreModel(const VesselRef& vessel, const nlohmann::json& model, bool measured,
                ResultRow& row) {
  double precision = 0.0, recall = 0.0;
  int known = 0;
  row.terms = 0;
  const ModelView view(model);
  if (!view.HasEquations()) {
    // A vessel model: its complexity is what was fitted (refit's parameters, and diagnose's
    // effects or hybrid's missing terms).
    if (const nlohmann::json& refit = view.Section(std::string(kRefitMethodName)); !refit.is_null())
      row.terms = static_cast<int>(refit.at("free").size());
    row.terms += static_cast<int>(view.Effects().size());
    return;
  }
  for (const auto& [state, text] : view.Equations()) {
    row.terms += TermCount(text);
    if (const auto truth = TrueTerms(vessel.Name(), state)) {
      const StructureScore s = ScoreStructure(text, *truth);
      precision += s.precision;
      recall += s.recall;
      ++known;
    }
  }
  if (known > 0) {
    row.precision = precision / known;
    row.recall = recall / known;
  }
  if (measured || vessel.empty()) return;  // no true parameters to compare with
  const VesselInfo& info = vessel.Info();
  double worst = -1.0;
  for (size_t i = 0; i < info.params.size(); ++i)
    if (const std::optional<double> p = view.Parameter(info.params[i]))
      worst = std::max(worst, std::abs(*p / info.default_params[i] - 1.0));
  if (worst >= 0) row.parameter_error = worst;
}

// What a row's model was driven by: its inputs, and the force map that derived them.
std::string InputsOf(const nlohmann::json& model) {
  const ModelView view(model);
  std::string text;
  if (const std::string forces = view.Forces(); !forces.empty()) text = "forces " + forces + ": ";
  const std::vector<std::string> inputs = view.Inputs();
  for (size_t i = 0; i < inputs.size(); ++i) text += (i ? "," : "") + inputs[i];
  return text;
}

// A job's request. Where the records log disturbances, a method whose equations take any input
// reads them beside its default inputs (the commands, or the force map's forces), unless the
// suite names its inputs.
IdentifyRequest RequestFor(const Suite& suite, const FitJob& job) {
  IdentifyRequest r = FitRequest(job.method.method, job.method.options, job.vessel, job.seed);
  r.threads = 1;  // the suite runs jobs in parallel
  r.data_name = job.vessel.Name() + "/" + job.train_maneuver;
  if (!suite.conditions.logged.empty() && !job.vessel.empty() &&
      FindSuiteMethod(job.method.method).any_inputs && !job.method.options.contains("inputs")) {
    r.inputs = DefaultChannels(r).inputs;
    for (std::string& c : LoggedInputChannels(suite.conditions.logged)) r.inputs.push_back(c);
  }
  return r;
}

// The states a model is scored on: those it has equations for, or a vessel model's states.
std::vector<std::string> ScoredStates(const nlohmann::json& model) {
  const ModelView view(model);
  if (view.HasEquations()) return view.EquationStates();
  std::vector<std::string> states;
  for (const std::string& name : view.States())
    if (!IsPositionOrHeading(name)) states.push_back(name);
  return states;
}

// The maneuver a test was run with: its name in a simulated suite, the test data's declared
// "maneuver" on measured data ("" when it declares none: recorded inputs only).
std::string TestManeuverSpec(const Suite& suite, const std::string& test) {
  if (!suite.Measured()) return test;
  for (const SuiteData& d : suite.test_data)
    if (d.name == test) return d.maneuver;
  return "";
}

// The closed_loop of a row whose test was not replayed, saying why.
nlohmann::json NotReplayed(const Suite& suite, const std::string& test, const std::string& why) {
  return {{"maneuver", TestManeuverSpec(suite, test)}, {"status", "not replayed: " + why}};
}

// The records a run simulates, each simulated once: every method of a vessel, training maneuver,
// noise and seed trains on the same record, and every cell of a vessel, noise and seed tests on
// the same records (the default suite simulated each 5 or 10 times). A record is a pure function of
// its key within a run (one suite, one set of conditions), so a kept record is the record.
// Thread-safe; two cells that ask for a record at once may both simulate it (the same data).
class SimulatedRecords {
 public:
  explicit SimulatedRecords(const Suite& suite) : suite_(suite) {}

  std::shared_ptr<const Dataset> Get(const VesselRef& vessel, const std::string& maneuver,
                                     double seconds, double noise, uint64_t seed) {
    const Key key{vessel.Name(), maneuver, seconds, noise, seed};
    {
      std::lock_guard lock(mutex_);
      if (auto it = kept_.find(key); it != kept_.end()) return it->second;
    }
    auto record = std::make_shared<const Dataset>(
        SimulateForSuite(vessel, maneuver, seconds, noise, seed, suite_.conditions));
    std::size_t bytes = static_cast<std::size_t>(record->rows()) * sizeof(double);
    for (const Channel& c : record->channels()) bytes += c.StorageBytes();
    std::lock_guard lock(mutex_);
    // Kept up to kMaxBytes in all; beyond, simulated on every use as before.
    if (bytes_ + bytes <= kMaxBytes && kept_.emplace(key, record).second) bytes_ += bytes;
    return record;
  }

 private:
  static constexpr std::size_t kMaxBytes = std::size_t{512} << 20;
  using Key = std::tuple<std::string, std::string, double, double, uint64_t>;
  const Suite& suite_;
  std::mutex mutex_;
  std::map<Key, std::shared_ptr<const Dataset>> kept_;
  std::size_t bytes_ = 0;
};

// A fold's training data: every run but the one it leaves out, joined (core/records.h) as a
// training entry of several files is.
Dataset FoldTrainingData(const Suite& suite, const std::string& train,
                         const std::map<std::string, Dataset>& runs) {
  std::vector<Dataset> records;
  for (const std::string& run : FoldTrainingRuns(suite, train)) records.push_back(runs.at(run));
  return JoinRecords(std::move(records));
}

}  // namespace

bool ReportDrawsFreeRun(const Suite& suite, const ResultRow& row) {
  return row.noise == suite.noise.front() && row.seed == suite.seeds.front() &&
         (suite.Measured() || row.test_maneuver == suite.test_maneuvers.front());
}

namespace {

// A test record whose log names its maneuver (metrics/maneuver_header.h) is read against that
// name before any fit: a name the record contradicts, or one usvid does not know, stops the run
// (InputError naming the file: exit 2), rather than failing every row that replays it.
void CheckNamedManeuver(const Dataset& record, const VesselRef& vessel) {
  if (!record.metadata().contains("maneuver") || vessel.empty()) return;
  const Actuation& act = vessel.Info().actuation;
  ReadTestOfRecord(record, "any", record.Has("psi") ? "psi" : "chi",
                   act.input_names.at(act.yaw_input));
}

// The row of `job`'s fit (`model`, or its `failure`) on the test maneuver `test`. Never throws.
ResultRow ScoreOnTest(const Suite& suite, const FitJob& job, const ResultRow& base,
                      const nlohmann::json& model, const std::string& failure,
                      const std::string& test, const std::map<std::string, Dataset>& test_sets,
                      SimulatedRecords& simulated) {
  ResultRow row = base;
  row.test_maneuver = test;
  row.model = model;
  row.inputs = InputsOf(model);
  if (!failure.empty()) {
    row.status = failure;
    row.closed_loop = NotReplayed(suite, test, "the fit failed, there is no model");
    return row;
  }
  try {
    const std::shared_ptr<const Dataset> simulated_held =
        suite.Measured()
            ? nullptr
            : simulated.Get(job.vessel, test, suite.test_seconds, job.noise, row.test_seed);
    const Dataset& held = simulated_held ? *simulated_held : test_sets.at(test);
    Evaluation evaluation = EvaluateModel(model, held, EvaluationScope::kRowScores);
    const Scores& e = evaluation.scores;
    for (const auto& [channel, score] : e.channels)
      row.channel_fit_percent[channel] = score.fit_percent;
    double sum = 0.0;
    for (const std::string& state : ScoredStates(model)) {
      row.fit_percent[state] = e.channels.at(state).fit_percent;
      row.nrmse[state] = e.channels.at(state).nrmse;
      sum += row.fit_percent[state];
    }
    row.mean_fit_percent = sum / static_cast<double>(row.fit_percent.size());
    if (e.regimes)
      for (const auto& [regime, scores] : *e.regimes) {
        double regime_sum = 0.0;
        for (const auto& [state, _] : row.fit_percent)
          regime_sum += scores.channels.at(state).fit_percent;
        row.regime_fit_percent[regime] = regime_sum / static_cast<double>(row.fit_percent.size());
      }
    for (const auto& [horizon, fits] : e.horizon_fit_percent) {
      double horizon_sum = 0.0;
      for (const auto& [state, _] : row.fit_percent) horizon_sum += fits.at(state);
      row.horizon_fit_percent[horizon] = horizon_sum / static_cast<double>(row.fit_percent.size());
    }
    if (e.valid_prediction_s) row.valid_prediction_s = *e.valid_prediction_s;
    for (const auto& [state, r2] : e.derivative_r2)
      if (std::isfinite(r2)) row.derivative_r2[state] = r2;
    ScoreModel(job.vessel, model, suite.Measured(), row);
    row.diverged = e.diverged;
    row.diverged_at_s = e.diverged_at_s;
    row.diverged_channel = e.diverged_channel;
    const bool drawn = ReportDrawsFreeRun(suite, row);
    if (drawn) row.free_run = std::make_shared<const FreeRun>(std::move(evaluation.run));
    const std::string spec = TestManeuverSpec(suite, test);
    ClosedLoopReplay replay;
    row.closed_loop = ClosedLoopScore(
        model, job.vessel, suite.Measured() ? RecordedManeuverSpec(spec, job.vessel, held) : spec,
        held, &replay);
    if (suite.Measured() && drawn && replay.run.rows() > 0)
      row.replay = std::make_shared<const ClosedLoopReplay>(std::move(replay));
  } catch (const std::exception& e) {
    row.status = std::string("failed: ") + e.what();
    row.closed_loop = NotReplayed(suite, test, "the model's evaluation failed");
  }
  return row;
}

// One cell: the job's fit, scored on every test maneuver (a fold's: on the run it leaves out).
// Never throws: a failure is a row.
std::vector<ResultRow> RunCell(const Suite& suite, const FitJob& job,
                               const std::map<std::string, Dataset>& train_sets,
                               const std::map<std::string, Dataset>& test_sets,
                               SimulatedRecords& simulated) {
  ResultRow base;
  base.vessel = job.vessel.empty() ? suite.name : job.vessel.Name();  // vessel-less data: the suite
  base.train_maneuver = TrainingLabel(suite, job.train_maneuver);
  base.method = job.method.Label();
  base.noise = job.noise;
  base.seed = job.seed;
  base.test_seed = job.seed + 1000;
  nlohmann::json model;
  std::string failure;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::shared_ptr<const Dataset> train;
    if (suite.cv.On())
      train =
          std::make_shared<const Dataset>(FoldTrainingData(suite, job.train_maneuver, test_sets));
    else if (!suite.Measured())
      train =
          simulated.Get(job.vessel, job.train_maneuver, suite.train_seconds, job.noise, job.seed);
    const Dataset& train_data = train ? *train : train_sets.at(job.train_maneuver);
    model = Fit(FindSuiteMethod(job.method.method), train_data, RequestFor(suite, job));
  } catch (const std::exception& e) {
    failure = std::string("failed: ") + e.what();
  }
  base.fit_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Each test is scored apart; in a suite a thread out of cells takes some (core/parallel_for.h).
  const std::vector<std::string> tests = ScoredTests(suite, job.train_maneuver);
  std::vector<ResultRow> rows(tests.size());
  ParallelFor(static_cast<int>(tests.size()), 1, [&](int i) {
    rows[i] = ScoreOnTest(suite, job, base, model, failure, tests[i], test_sets, simulated);
  });
  return rows;
}

}  // namespace

std::map<size_t, std::vector<ResultRow>> RunCells(
    const Suite& suite, const std::vector<FitJob>& jobs, int threads,
    const std::function<std::optional<size_t>()>& next,
    const std::function<void(size_t, const std::vector<ResultRow>&)>& done) {
  // Measured data are read once, before the parallel part (a bad file stops the run: exit 2). A
  // cross-validated suite's runs are its test data; each fold joins the others as it starts.
  std::map<std::string, Dataset> train_sets, test_sets;
  if (!suite.cv.On())
    for (const SuiteData& d : suite.train_data) train_sets[d.name] = LoadSuiteData(d);
  for (const SuiteData& d : suite.test_data) {
    test_sets[d.name] = LoadSuiteData(d);
    CheckNamedManeuver(test_sets[d.name],
                       suite.vessels.empty() ? VesselRef() : suite.vessels.front());
  }
  std::map<size_t, std::vector<ResultRow>> cells;
  SimulatedRecords simulated(suite);
  if (threads > 0) omp_set_num_threads(threads);
  std::string save_failure;
#pragma omp parallel
  while (true) {
    std::optional<size_t> j;
#pragma omp critical(usvid_next_cell)
    j = save_failure.empty() ? next() : std::nullopt;
    if (!j) break;
    std::vector<ResultRow> rows = RunCell(suite, jobs.at(*j), train_sets, test_sets, simulated);
    // The callback saves the cell; a failure to save ends the run once the running cells are
    // done (no exception may leave the parallel region).
#pragma omp critical(usvid_next_cell)
    {
      try {
        if (done) done(*j, rows);
      } catch (const std::exception& e) {
        if (save_failure.empty()) save_failure = e.what();
      }
      cells[*j] = std::move(rows);
    }
  }
  if (!save_failure.empty()) throw InputError(save_failure);
  return cells;
}

std::vector<size_t> SlowestFirst(const std::vector<FitJob>& jobs, std::vector<size_t> cells) {
  std::map<size_t, double> cost;  // each job's, once
  for (size_t j : cells) {
    const SuiteMethod& m = jobs.at(j).method;
    const Method& method = FindSuiteMethod(m.method);
    cost[j] = method.relative_cost;
    if (method.cost_scale) {
      const MethodOptions options =
          ValidateOptions(method.name, method.options, m.OwnOptions(), "suite");
      cost[j] *= method.cost_scale(options);
    }
  }
  std::stable_sort(cells.begin(), cells.end(),
                   [&](size_t a, size_t b) { return cost.at(a) > cost.at(b); });
  return cells;
}

std::vector<ResultRow> RunSuite(const Suite& suite, int threads,
                                const std::function<void(const std::string&)>& progress) {
  const std::vector<FitJob> jobs = FitJobs(suite);
  std::vector<size_t> all(jobs.size());
  std::iota(all.begin(), all.end(), size_t{0});
  const std::vector<size_t> order = SlowestFirst(jobs, std::move(all));
  size_t handed_out = 0, finished = 0;
  const auto cells = RunCells(
      suite, jobs, threads,
      [&]() -> std::optional<size_t> {
        if (handed_out == order.size()) return std::nullopt;
        return order[handed_out++];
      },
      [&](size_t j, const std::vector<ResultRow>& rows) {
        ++finished;
        if (progress) progress(CellProgress(finished, jobs.size(), jobs[j], rows));
      });
  std::vector<ResultRow> out;
  for (const auto& [_, rows] : cells) out.insert(out.end(), rows.begin(), rows.end());
  return out;
}

std::string CellProgress(size_t finished, size_t total, const FitJob& job,
                         const std::vector<ResultRow>& rows) {
  // The job's id with its vessel named as a reader knows it (a vessel file's name:, not its path).
  const std::string id = job.Id();
  std::string line = "[" + std::to_string(finished) + "/" + std::to_string(total) + "] " +
                     (id.starts_with(job.vessel.Name()) && !job.vessel.empty()
                          ? VesselLabel(job.vessel.Name()) + id.substr(job.vessel.Name().size())
                          : id);
  // A fit that failed fails every test row the same way: say it once.
  if (!rows.empty() && rows.front().status != "ok" &&
      std::all_of(rows.begin(), rows.end(),
                  [&](const ResultRow& r) { return r.status == rows.front().status; }))
    line += " " + rows.front().status;
  return line;
}

}  // namespace usvid
