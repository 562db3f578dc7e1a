// HSVA free-running model test files (SIMMAN 2008 KVLCC2, model scale 1:45.7, run under the
// CPMC carriage): cp1252 text, four header lines (institute, ship, the maneuver as in
// "Z20°/10° starting to starboard", a title), then 12 whitespace-separated columns at 20 Hz
//   time [s], x0 [m], y0 [m], psi [deg], dx0/dt [m/s], dy0/dt [m/s], r [deg/s], phi [deg],
//   delta [deg], rev [rps], thrust [N], torque [N m]
// where dx0/dt, dy0/dt are earth-fixed. The import gives the kvlcc2 channels of docs/data.md:
// north, east, psi, u, v (body-fixed, earth_to_body.h), r [rad/s], delta [rad] (as logged:
// negative turns to starboard, as in MARIN's files), rev [rpm] (x60), and phi [rad], thrust [N],
// torque [N m] as extras, all at the log's scale (`usvid import --scale 45.7` takes them to the
// ship). The third header line, converted to UTF-8 and trimmed, is kept as metadata "maneuver"
// and not interpreted; metadata "format" is "hsva-dat".
// Throws InputError "file:line:column: what" for fewer than 4 header lines (a row of numbers
// where a header line belongs), an empty maneuver line, a byte cp1252 does not define or a
// control character in the header, no data rows, a row of another length than 12, a cell that
// is not a finite number, and time that does not increase strictly.
#pragma once

#include <string>

#include "core/dataset.h"
#include "importers/import_report.h"

namespace usvid {

Dataset ImportHsvaDat(const std::string& path, ImportReport& report);
Dataset ParseHsvaDat(const std::string& text, const std::string& file, ImportReport& report);

}  // namespace usvid
