// diagnosis.json (docs/data.md#diagnosisjson) and the extended model's model.json.
#pragma once

#include <nlohmann/json.hpp>

#include "diagnosis/diagnose.h"

namespace usvid::diagnosis {

nlohmann::json DiagnosisToJson(const Diagnosis& d);

// The nominal vessel with the cause's fitted effect: method "diagnose", vessel, parameters,
// effects (as `simulate --effect` takes them), and the held-out fit before and after.
nlohmann::json ExtendedModelJson(const Diagnosis& d);

}  // namespace usvid::diagnosis
