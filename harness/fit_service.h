// One fit, as `usvid identify`, a suite's cell and Python's identify run it: the request built
// from a method's options and the keys every method shares (declared once, here), the method,
// and the steps after it (a model's closed-loop choice and r's calibration, metrics/). The three
// callers differ only in where the options come from: flags, a suite's method entry, keywords.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/identify_request.h"
#include "methods/method.h"
#include "methods/method_options.h"
#include "simulation/vessel_ref.h"

namespace usvid {

// The keys a method entry may give besides the method's own options: the channels (states,
// inputs) and the preprocessing every method shares (rate, forces, derivative). On `usvid
// identify` they are the flags --states, --inputs, --rate, --forces, --derivative.
const std::vector<OptionSpec>& SharedFitOptions();

// Whether `key` is one of SharedFitOptions.
bool IsSharedFitKey(const std::string& key);

// `options` less the shared keys: the method's own, as declared.
nlohmann::json OwnFitOptions(const nlohmann::json& options);

// The request that `options` (the method's own and the shared keys, as checked values) make for
// `method` on `vessel`'s data ("" when the options name the channels), at `seed`, over the
// caller's other preprocessing `base` (the command line's --interpolation, --delay, ...). Unset,
// forces is the waterjet map for a method that takes inputs as channels on a vessel that logs
// its jets (and no inputs named), else none. Threads and the data's name are the caller's.
IdentifyRequest FitRequest(const std::string& method, const nlohmann::json& options,
                           const VesselRef& vessel, uint64_t seed,
                           const PreprocessOptions& base = {});

// `method` fitted to `data` by `request` (methods/identify.h), then the steps the model asks
// for after its fit (metrics/yaw_bias_calibration.h: CalibrateRequested). Throws as Identify.
nlohmann::json Fit(const Method& method, const Dataset& data, const IdentifyRequest& request,
                   const Logger& log = {});

}  // namespace usvid
