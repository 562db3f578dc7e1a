#include "methods/lti/lti.h"

#include <Eigen/QR>
#include <cmath>

#include "core/error.h"
#include "core/expression.h"
#include "core/parse_number.h"

namespace usvid::lti {
namespace {

const Eigen::VectorXd& Column(const Dataset& data, const std::string& name) {
  if (!data.Has(name)) throw InputError("lti: the data have no channel '" + name + "'");
  const Eigen::VectorXd& c = data[name];
  if (!c.allFinite()) throw InputError("lti: channel '" + name + "' is not finite everywhere");
  return c;
}

}  // namespace

LtiIdentification IdentifyLti(const PreparedData& prepared, const std::vector<std::string>& states,
                              const std::vector<std::string>& variables,
                              const std::vector<std::string>& inputs, const LtiOptions& options) {
  if (!(std::isfinite(options.ridge) && options.ridge >= 0))
    throw InputError("lti: ridge must be finite and >= 0, not " + FormatNumber(options.ridge));
  const Dataset& data = prepared.data;
  std::vector<std::string> terms;
  if (options.constant) terms.push_back("1");
  for (const auto& names : {variables, inputs})
    terms.insert(terms.end(), names.begin(), names.end());
  const Eigen::Index rows = data.rows(), k = static_cast<Eigen::Index>(terms.size());
  if (rows <= k)
    throw InputError("lti: " + std::to_string(rows) + " rows cannot fit " + std::to_string(k) +
                     " terms");
  // The regression with the ridge's rows below it: [A; sqrt(ridge) diag(|a_j|)] w = [y; 0].
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows + k, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const std::string& term = terms[static_cast<size_t>(j)];
    a.col(j).head(rows) =
        term == "1" ? Eigen::VectorXd::Ones(rows) : Eigen::VectorXd(Column(data, term));
    if (term != "1") a(rows + j, j) = std::sqrt(options.ridge) * a.col(j).head(rows).norm();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  LtiIdentification id;
  for (const std::string& state : states) {
    const Eigen::VectorXd& y = Column(data, state + "_dot");
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows + k);
    rhs.head(rows) = y;
    const Eigen::VectorXd w = qr.solve(rhs);
    id.equations[state] = WeightedSumText(terms, w);
    for (Eigen::Index j = 0; j < k; ++j)
      id.parameters[state + "." + terms[static_cast<size_t>(j)]] = w(j);
    const double sst = (y.array() - y.mean()).square().sum();
    const double ssr = (y - a.topRows(rows) * w).squaredNorm();
    id.details[state] = {
        {"terms", terms}, {"r2_train", sst > 0 ? 1.0 - ssr / sst : 0.0}, {"rank", qr.rank()}};
  }
  return id;
}

}  // namespace usvid::lti
