// Every method a suite may list, in one registry: the identification methods (methods/registry.h)
// and, after them, the suite's own two, as Methods like any other (a name, declared options, a
// function from the training record to model.json):
//  - diagnose: the nominal vessel extended by the causes `usvid diagnose` names on the training
//    record (diagnosis/diagnose.h); a vessel model;
//  - external: a command outside usvid, run on the training record (harness/external_method.h).
// The harness checks, fits and labels through this registry. One method it tells apart by its
// name constant, kExternalMethod: an external row is labelled by its `name` option and keeps no
// model to re-score (harness/suite.cc, harness/cell_store.cc).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "methods/method.h"

namespace usvid {

// The suite's own method beside the registered ones: the nominal vessel, diagnosed.
inline constexpr std::string_view kDiagnoseMethod = "diagnose";

// The registered methods in their order, then diagnose and external.
const std::vector<Method>& SuiteMethods();

// Throws InputError naming the unknown method and the known ones.
const Method& FindSuiteMethod(std::string_view name);

}  // namespace usvid
