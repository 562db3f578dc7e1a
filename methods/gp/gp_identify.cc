#include "methods/gp/gp_identify.h"

#include <sstream>

#include "core/error.h"

namespace usvid::gp {

std::vector<Op> ParseOperators(const std::string& list) {
  static const std::pair<const char*, Op> kKnown[] = {
      {"+", Op::kAdd},   {"-", Op::kSub},     {"*", Op::kMul},   {"/", Op::kDiv},
      {"abs", Op::kAbs}, {"tanh", Op::kTanh}, {"sin", Op::kSin}, {"cos", Op::kCos},
      {"exp", Op::kExp}, {"sqrt", Op::kSqrt}};
  std::vector<Op> ops;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    bool found = false;
    for (const auto& [name, op] : kKnown)
      if (item == name) {
        if (std::find(ops.begin(), ops.end(), op) == ops.end()) ops.push_back(op);
        found = true;
      }
    if (!found)
      throw InputError("--operators: unknown operator '" + item +
                       "' (known: + - * / abs tanh sin cos exp sqrt)");
  }
  if (ops.empty()) throw InputError("--operators: the list is empty");
  return ops;
}

std::string OperatorList(const std::vector<Op>& ops) {
  std::string s;
  for (Op op : ops) s += (s.empty() ? "" : ",") + std::string(Symbol(op));
  return s;
}

GpIdentification IdentifyWithGp(
    const PreparedData& prepared, const std::vector<std::string>& states,
    const std::vector<std::string>& variables, const std::vector<std::string>& inputs,
    const GpOptions& options,
    const std::function<void(const std::string&, const GenerationLog&)>& progress) {
  GpProblem problem;
  for (const auto& names : {variables, inputs})
    for (const std::string& n : names) {
      problem.names.push_back(n);
      problem.variables.push_back(prepared.data[n]);
    }
  GpIdentification out;
  for (const std::string& state : states) {
    problem.target = prepared.data[state + "_dot"];
    const GpResult r = RunGp(problem, options, [&](const GenerationLog& log) {
      if (progress) progress(state, log);
    });
    out.node_evaluations += r.node_evaluations;
    out.equations[state] = r.best.Equation(problem.names);
    out.parameters[state + ".bias"] = r.best.bias;
    for (size_t t = 0; t < r.best.weights.size(); ++t)
      out.parameters[state + ".w" + std::to_string(t + 1)] = r.best.weights[t];
    nlohmann::json pareto = nlohmann::json::array();
    for (const ParetoPoint& p : r.pareto)
      pareto.push_back({{"size", p.size}, {"mse", p.mse}, {"equation", p.equation}});
    nlohmann::json log = nlohmann::json::array();
    for (const GenerationLog& g : r.log)
      log.push_back({{"generation", g.generation},
                     {"best_fitness", g.best_fitness},
                     {"best_r2", g.best_r2},
                     {"best_size", g.best_size},
                     {"mean_size", g.mean_size}});
    out.details[state] = {{"r2_train", r.best.r2},
                          {"size", r.best.Size()},
                          {"generations", r.log.size()},
                          {"stop_reason", r.stop_reason},
                          {"evaluations", r.evaluations},
                          {"pareto", pareto},
                          {"log", log}};
  }
  return out;
}

}  // namespace usvid::gp
