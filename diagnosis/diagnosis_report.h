// The diagnosis as a person reads it: DIR/heldout.svg (each scored channel on the held-out part:
// measured, nominal and extended model, each segment from its estimated initial state), and
// DIR/report.html, self-contained, with the cause and gain, the ranked candidates, the residual
// signatures and the plot inline. Throws InputError when a file cannot be written (atomic: nothing
// half-written is left).
#pragma once

#include <string>

#include "diagnosis/diagnose.h"

namespace usvid::diagnosis {

void WriteDiagnosisReport(const Diagnosis& d, const std::string& dir);

}  // namespace usvid::diagnosis
