#include "preprocessing/regressor_library.h"

#include <Eigen/QR>
#include <algorithm>

#include "core/expression.h"
#include "preprocessing/rudder_inflow.h"

namespace usvid {

namespace {

// The states and inputs, in that order.
std::vector<const NamedSignal*> AllSignals(const std::vector<NamedSignal>& states,
                                           const std::vector<NamedSignal>& inputs) {
  std::vector<const NamedSignal*> all;
  for (const auto* list : {&states, &inputs})
    for (const NamedSignal& s : *list) all.push_back(&s);
  return all;
}

// `expression`, in the signals' names, evaluated at every row into `out`.
void EvaluateInto(const std::string& expression, const std::vector<const NamedSignal*>& signals,
                  double* out) {
  const Expression e = Expression::Parse(expression, "rudder inflow");
  std::vector<const double*> columns;
  for (const std::string& v : e.Variables())
    columns.push_back((*std::ranges::find(signals, v, [](const NamedSignal* s) {
                        return s->name;
                      }))->values.data());
  e.EvaluateColumns(columns, signals.front()->values.size(), out);
}

}  // namespace

RegressorLibrary BuildLibrary(const std::vector<NamedSignal>& states,
                              const std::vector<NamedSignal>& inputs,
                              const LibraryOptions& options) {
  const Eigen::Index n = !states.empty()   ? states[0].values.size()
                         : !inputs.empty() ? inputs[0].values.size()
                                           : 0;
  // The columns are written straight into the matrix, in the order of their names: a long
  // record's library is held once, not also as a list of columns.
  std::vector<std::string> names;
  if (options.constant) names.push_back("1");
  for (const NamedSignal& x : states) names.push_back(x.name);
  if (options.products)
    for (size_t i = 0; i < states.size(); ++i)
      for (size_t k = i; k < states.size(); ++k)
        names.push_back(states[i].name + "*" + states[k].name);
  if (options.abs_terms)
    for (const NamedSignal& x : states) names.push_back("abs(" + x.name + ")*" + x.name);
  for (const NamedSignal& u : inputs) names.push_back(u.name);
  if (options.input_products) {
    for (const NamedSignal& x : states)
      for (const NamedSignal& u : inputs) names.push_back(x.name + "*" + u.name);
    for (size_t j = 0; j < inputs.size(); ++j)
      for (size_t m = j; m < inputs.size(); ++m)
        names.push_back(inputs[j].name + "*" + inputs[m].name);
    for (const NamedSignal& u : inputs) names.push_back("abs(" + u.name + ")*" + u.name);
  }

  const std::vector<const NamedSignal*> signals = AllSignals(states, inputs);
  std::vector<RudderInflowTerm> inflow;
  if (options.rudder_inflow) {
    std::vector<std::string> channels;
    for (const NamedSignal* s : signals) channels.push_back(s->name);
    inflow = RudderInflowTerms(channels);
  }
  for (const RudderInflowTerm& term : inflow) names.push_back(term.expression);

  RegressorLibrary lib{names, Eigen::MatrixXd(n, static_cast<Eigen::Index>(names.size()))};
  Eigen::Index c = 0;
  if (options.constant) lib.columns.col(c++).setOnes();
  for (const NamedSignal& x : states) lib.columns.col(c++) = x.values;
  if (options.products)
    for (size_t i = 0; i < states.size(); ++i)
      for (size_t k = i; k < states.size(); ++k)
        lib.columns.col(c++) = states[i].values.cwiseProduct(states[k].values);
  if (options.abs_terms)
    for (const NamedSignal& x : states)
      lib.columns.col(c++) = x.values.cwiseAbs().cwiseProduct(x.values);
  for (const NamedSignal& u : inputs) lib.columns.col(c++) = u.values;
  if (options.input_products) {
    for (const NamedSignal& x : states)
      for (const NamedSignal& u : inputs) lib.columns.col(c++) = x.values.cwiseProduct(u.values);
    for (size_t j = 0; j < inputs.size(); ++j)
      for (size_t m = j; m < inputs.size(); ++m)
        lib.columns.col(c++) = inputs[j].values.cwiseProduct(inputs[m].values);
    for (const NamedSignal& u : inputs)
      lib.columns.col(c++) = u.values.cwiseAbs().cwiseProduct(u.values);
  }
  for (const RudderInflowTerm& term : inflow)
    EvaluateInto(term.expression, signals, lib.columns.col(c++).data());
  return lib;
}

LinearFit FitLeastSquares(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target) {
  // Columns scaled to unit RMS so that N and rad/s sit in one well-conditioned problem.
  Eigen::VectorXd scale = (columns.colwise().squaredNorm() / std::max<double>(1, columns.rows()))
                              .cwiseSqrt()
                              .transpose();
  for (Eigen::Index c = 0; c < scale.size(); ++c)
    if (scale(c) == 0.0) scale(c) = 1.0;
  const Eigen::MatrixXd a = columns * scale.cwiseInverse().asDiagonal();
  LinearFit fit;
  fit.weights = a.colPivHouseholderQr().solve(target).cwiseQuotient(scale);
  const Eigen::VectorXd residual = target - columns * fit.weights;
  fit.ssr = residual.squaredNorm();
  const double sst = (target.array() - target.mean()).square().sum();
  fit.r2 = sst > 0 ? 1.0 - fit.ssr / sst : 0.0;
  return fit;
}

}  // namespace usvid
