#include "preprocessing/rudder_inflow.h"

#include <algorithm>

namespace usvid {

std::vector<RudderInflowTerm> RudderInflowTerms(const std::vector<std::string>& channels) {
  const auto has = [&](const char* name) {
    return std::ranges::find(channels, name) != channels.end();
  };
  std::vector<RudderInflowTerm> terms;
  if (!has("delta")) return terms;
  if (has("u")) terms.push_back({"delta_uu", "abs(u)*u*delta"});
  const std::string n = has("n") ? "n" : has("rev") ? "rev" : "";
  if (n.empty()) return terms;
  const std::string ahead = "(" + n + "+abs(" + n + "))";
  if (has("u")) terms.push_back({"delta_un", "u*" + ahead + "*delta"});
  terms.push_back({"delta_nn", ahead + "*" + ahead + "*delta"});
  return terms;
}

}  // namespace usvid
