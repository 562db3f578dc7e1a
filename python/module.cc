// The Python module `usvid` (docs/python.md): the library's simulate, identify, evaluate,
// diagnose and compare, with numpy arrays for data and dicts for JSON. Every call converts its
// arguments while it holds the GIL, then releases it for the work; InputError becomes
// ValueError with the same message as the command line's.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json_file.h"
#include "core/records.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/diagnosis_json.h"
#include "effects/effect.h"
#include "harness/fit_service.h"
#include "harness/results.h"
#include "harness/run_suite.h"
#include "harness/suite.h"
#include "methods/identify.h"
#include "methods/registry.h"
#include "metrics/evaluation.h"
#include "python/python_data.h"
#include "simulation/simulate_record.h"
#include "simulation/vessel_simulator.h"

namespace py = pybind11;

namespace usvid::python {
namespace {

// `effects`: None, a list of "NAME=VALUE" strings as `usvid simulate --effect` takes, or a dict
// of name to value.
std::vector<std::string> EffectSpecs(const py::object& effects) {
  std::vector<std::string> specs;
  if (effects.is_none()) return specs;
  if (py::isinstance<py::dict>(effects)) {
    for (const auto& [name, value] : effects.cast<py::dict>())
      specs.push_back(py::str(name).cast<std::string>() + "=" + py::str(value).cast<std::string>());
    return specs;
  }
  for (const auto& item : effects) specs.push_back(py::str(item).cast<std::string>());
  return specs;
}

py::dict Simulate(const std::string& vessel, const py::object& maneuver, const py::object& inputs,
                  const py::object& effects, double noise, uint64_t seed,
                  const py::object& duration) {
  if (maneuver.is_none() == inputs.is_none())
    throw InputError("simulate: give exactly one of maneuver and inputs");
  if (!(noise >= 0)) throw InputError("simulate: noise must be >= 0");
  const double seconds = duration.is_none() ? 0.0 : duration.cast<double>();
  if (!(seconds >= 0)) throw InputError("simulate: duration must be >= 0 (0: the maneuver's)");
  const std::vector<std::string> specs = EffectSpecs(effects);
  const std::string spec = maneuver.is_none() ? "" : maneuver.cast<std::string>();
  const Dataset recorded = inputs.is_none() ? Dataset() : ToDataset(inputs.cast<py::dict>());
  Dataset data;
  {
    py::gil_scoped_release release;
    RecordRecipe recipe;
    recipe.vessel = vessel;
    recipe.maneuver = spec;
    recipe.inputs = spec.empty() ? &recorded : nullptr;
    recipe.duration_s = seconds;
    recipe.effects = ParseEffects(specs, seed);
    recipe.sensors.noise = noise;
    recipe.seed = seed;
    SimulatedRecord record = SimulateRecord(recipe);
    if (record.diverged)
      throw InputError("simulate: the " + recipe.vessel.Info().name +
                       " simulation diverged at t = " + std::to_string(record.diverged_at_s) +
                       " s");
    data = std::move(record.data);
  }
  return ToDict(data);
}

// identify's keyword options: the method's declared options and the keys every method shares,
// as a suite's method entry takes them (harness/suite.h), plus threads and seed.
py::dict Identify(const py::object& data, const std::string& method, const py::object& vessel,
                  const py::object& states, const py::object& inputs, const py::kwargs& kwargs) {
  nlohmann::json options = ToJson(kwargs);
  // threads and seed, as `usvid identify --threads --seed`; the rest as a suite's options.
  auto take = [&](const char* key, int64_t fallback) {
    if (!options.contains(key)) return fallback;
    const nlohmann::json value = options[key];
    if (!value.is_number_integer() || value.get<int64_t>() < 0)
      throw InputError(std::string("identify: ") + key + " must be a whole number >= 0");
    options.erase(key);
    return value.get<int64_t>();
  };
  const int threads = static_cast<int>(take("threads", 0));
  const auto seed = static_cast<uint64_t>(take("seed", 1));
  if (!states.is_none()) options["states"] = states.cast<std::vector<std::string>>();
  if (!inputs.is_none()) options["inputs"] = inputs.cast<std::vector<std::string>>();
  FindMethod(method);  // an unknown method is named before its options
  CheckSuiteMethod({method, options}, "identify");
  const std::string vessel_name = vessel.is_none() ? "" : vessel.cast<std::string>();
  IdentifyRequest request = FitRequest(method, options, vessel_name, seed);
  request.threads = threads;
  request.data_name = "python";
  // One record (a dict), or several fitted jointly (a list of dicts; core/records.h).
  Dataset d;
  if (py::isinstance<py::dict>(data)) {
    d = ToDataset(data.cast<py::dict>());
  } else {
    std::vector<Dataset> records;
    for (const py::handle record : data.cast<py::list>())
      records.push_back(ToDataset(record.cast<py::dict>()));
    if (records.empty()) throw InputError("identify: data: an empty list of records");
    d = JoinRecords(std::move(records));
  }
  nlohmann::json model;
  {
    py::gil_scoped_release release;
    model = Fit(FindMethod(method), d, request);
  }
  return FromJson(model);
}

py::dict Evaluate(const py::dict& model, const py::dict& data) {
  const nlohmann::json m = ToJson(model);
  const Dataset d = ToDataset(data);
  nlohmann::json metrics;
  {
    py::gil_scoped_release release;
    metrics = EvaluateModel(m, d).metrics;
  }
  return FromJson(metrics);
}

py::dict Diagnose(const py::dict& data, const std::string& vessel, int causes, bool discover) {
  if (causes < 1) throw InputError("diagnose: causes must be at least 1");
  const Dataset d = ToDataset(data);
  nlohmann::json out;
  {
    py::gil_scoped_release release;
    diagnosis::DiagnoseOptions options;
    options.max_causes = causes;
    options.discover = discover;
    const VesselRef ref(vessel);
    const diagnosis::Diagnosis result =
        diagnosis::Diagnose(d, ref, ref.Info().default_params, options);
    out = diagnosis::DiagnosisToJson(result);
    out["model"] = diagnosis::ExtendedModelJson(result);
  }
  return FromJson(out);
}

// `suite`: a suite as a dict, or the path of a suite file.
py::dict Compare(const py::object& suite, int threads) {
  if (threads < 0) throw InputError("compare: threads must be >= 0 (0: all cores)");
  const bool path = py::isinstance<py::str>(suite);
  const std::string file = path ? suite.cast<std::string>() : "suite";
  const Suite s =
      ParseSuite(path ? ReadJsonFile(file, JsonComments::kAllowed) : ToJson(suite), file);
  nlohmann::json results;
  {
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<ResultRow> rows = RunSuite(s, threads);
    results = ResultsJson(
        s, rows, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return FromJson(results);
}

}  // namespace
}  // namespace usvid::python

PYBIND11_MODULE(_usvid, m) {
  using namespace usvid::python;
  using py::arg;
  m.doc() = "usvid: identification of high-speed surface vessels (docs/python.md)";
  // A vessel file's notes to stderr, as the command line says them (no Python object touched).
  usvid::SetVesselNoteSink([](const std::string& note) { std::cerr << note << '\n'; });
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const usvid::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("simulate", &Simulate, arg("vessel"), arg("maneuver") = py::none(),
        arg("inputs") = py::none(), arg("effects") = py::none(), arg("noise") = 0.0,
        arg("seed") = 0, arg("duration") = py::none(),
        "A maneuver (or recorded inputs, a dict with 't') on a vessel: a dict of numpy arrays.");
  m.def("identify", &Identify, arg("data"), arg("method"), arg("vessel") = py::none(),
        arg("states") = py::none(), arg("inputs") = py::none(),
        "Fit a method to data (a dict, or a list of dicts fitted jointly): model.json as a dict. "
        "Options as a suite's (population=..., seed=..., threads=...).");
  m.def("evaluate", &Evaluate, arg("model"), arg("data"),
        "Free-run a model on data: metrics.json as a dict.");
  m.def("diagnose", &Diagnose, arg("data"), arg("vessel"), arg("causes") = 3,
        arg("discover") = true,
        "What the vessel's simulation gets wrong on data: diagnosis.json as a dict, with the "
        "extended model under 'model'.");
  m.def("compare", &Compare, arg("suite"), arg("threads") = 0,
        "Run a suite (a dict, or a suite file's path): results.json as a dict.");
  m.def(
      "vessels",
      [] {
        std::vector<std::string> names;
        for (const auto& name : usvid::VesselNames()) names.push_back(name);
        return names;
      },
      "The registered vessels' names.");
}
