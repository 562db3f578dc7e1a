#include "preprocessing/regressor_library.h"

#include <Eigen/QR>
#include <algorithm>

#include "core/expression.h"
#include "preprocessing/rudder_inflow.h"

namespace usvid {

namespace {

// The rudder-inflow columns of LibraryOptions::rudder_inflow, named by their expressions.
std::vector<NamedSignal> RudderInflowColumns(const std::vector<NamedSignal>& states,
                                             const std::vector<NamedSignal>& inputs,
                                             const LibraryOptions& options) {
  std::vector<NamedSignal> columns;
  if (!options.rudder_inflow) return columns;
  std::vector<const NamedSignal*> signals;
  std::vector<std::string> names;
  for (const auto* list : {&states, &inputs})
    for (const NamedSignal& s : *list) {
      signals.push_back(&s);
      names.push_back(s.name);
    }
  for (const RudderInflowTerm& term : RudderInflowTerms(names)) {
    const Expression e = Expression::Parse(term.expression, "rudder inflow");
    std::vector<const double*> columns_of;
    for (const std::string& v : e.Variables())
      columns_of.push_back(signals[std::ranges::find(names, v) - names.begin()]->values.data());
    NamedSignal column{term.expression, Eigen::VectorXd(signals.front()->values.size())};
    e.EvaluateColumns(columns_of, column.values.size(), column.values.data());
    columns.push_back(std::move(column));
  }
  return columns;
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

  const std::vector<NamedSignal> inflow = RudderInflowColumns(states, inputs, options);
  for (const NamedSignal& col : inflow) names.push_back(col.name);

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
  for (const NamedSignal& col : inflow) lib.columns.col(c++) = col.values;
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
