// The seconds-long variant of an embedded suite (usvid compare --suite NAME --quick; CI runs
// every embedded suite so, tests/apps/embedded_suites_smoke_test.cc): the same vessels, maneuvers,
// conditions and data, so that every reading and check the harness makes of its records runs, at
// a fraction of the fits. A simulated suite keeps its first noise level and first seed, records
// of at most 150 s to train and 90 s to test, and GP at the quick suite's search (population
// 300, 10 generations; harness/suites/quick.json). A suite on measured data keeps its runs and
// fits only the fast methods among its own (nominal, lti, nomoto, sindy).
#pragma once

#include "harness/suite.h"

namespace usvid {

Suite SmokeVariant(Suite suite);

}  // namespace usvid
