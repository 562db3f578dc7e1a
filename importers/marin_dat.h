// MARIN free-running model test files (SIMMAN 2008 KVLCC2, full-scale values): three header
// lines, then whitespace-separated columns
//   time [s], x0 [m], y0 [m], phi [deg], psi [deg], u [m/s], v [m/s], p [deg/s], r [deg/s],
//   delta [deg], rev [rpm]
// where u, v are earth-fixed (dx0/dt, dy0/dt). Every value has 3 significant digits, so time
// stamps repeat. The import gives the kvlcc2 channels of docs/data.md: north, east, psi, u, v, r
// (body-fixed, rad, rad/s), delta [rad], rev [rpm], and phi, p as extras; the time base is
// rebuilt (see time_repair.h) and the report says how many rows were repaired.
#pragma once

#include <string>

#include "core/dataset.h"
#include "importers/import_report.h"

namespace usvid {

Dataset ImportMarinDat(const std::string& path, ImportReport& report);
Dataset ParseMarinDat(const std::string& text, const std::string& file, ImportReport& report);

}  // namespace usvid
