#include "harness/smoke_suite.h"

#include <algorithm>
#include <set>
#include <string>

#include "methods/gp/gp_identify.h"
#include "methods/lti/lti.h"
#include "methods/nominal/nominal.h"
#include "methods/nomoto/nomoto.h"
#include "methods/sindy/sindy.h"

namespace usvid {

Suite SmokeVariant(Suite suite) {
  suite.name += "-quick";
  if (suite.Measured()) {
    static const std::set<std::string_view> kFast = {kNominalMethodName, lti::kMethodName,
                                                     nomoto::kMethodName, sindy::kMethodName};
    std::erase_if(suite.methods, [](const SuiteMethod& m) { return !kFast.contains(m.method); });
    return suite;
  }
  if (suite.noise.size() > 1) suite.noise.resize(1);
  if (suite.seeds.size() > 1) suite.seeds.resize(1);
  suite.train_seconds = std::min(suite.train_seconds, 150.0);
  suite.test_seconds = std::min(suite.test_seconds, 90.0);
  for (SuiteMethod& m : suite.methods)
    if (m.method == gp::kMethodName) {
      m.options["population"] = 300;
      m.options["generations"] = 10;
    }
  return suite;
}

}  // namespace usvid
