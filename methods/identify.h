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

// The request's options checked against `method`'s declaration (methods/method_options.h):
// throws InputError, prefixed by `where`, naming the method, the key and what is allowed.
MethodOptions CheckedOptions(const Method& method, const IdentifyRequest& request,
                             const std::string& where);

// `method` fitted to `data` with the request's options, checked first. Throws InputError for an
// option it does not take or a value out of range, or a combination it cannot fit. model.json's
// "options" echoes the options it ran with. `log` receives progress lines (may be empty). The
// data are taken by value: a caller done with them moves them in, and a long log is not held
// twice while derived channels are added.
nlohmann::json Identify(const Method& method, Dataset data, const IdentifyRequest& request,
                        const Logger& log = {});

// The registered method request.method (methods/registry.h); InputError for an unknown one.
nlohmann::json Identify(Dataset data, const IdentifyRequest& request, const Logger& log = {});

}  // namespace usvid
