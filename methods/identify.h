// One identification, whatever the method: speed and course (and the request's forces) derived,
// the registered method (methods/registry.h) fitted, and its model.json returned (method,
// vessel, states, variables, inputs, parameters, equations, seed, preprocessing, train, and the
// method's own details; docs/data.md). Used by `usvid identify`, the comparison harness and the
// design's checks.
#pragma once

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "methods/identify_request.h"
#include "methods/method.h"

namespace usvid {

// Throws InputError for an unknown method or a combination it cannot fit. `log` receives
// progress lines (may be empty). The data are taken by value: a caller done with them moves
// them in, and a long log is not held twice while derived channels are added.
nlohmann::json Identify(Dataset data, const IdentifyRequest& request, const Logger& log = {});

}  // namespace usvid
