// A vessel described by a file (YAML, or JSON, which YAML reads too) instead of the code: the
// main particulars of an MMG 3-DOF model (simulators/mmg.h), its controls, and whichever
// coefficients are known; the rest are estimated from the particulars by the published formulas
// of simulation/mmg_estimates.h. `--vessel FILE` takes it wherever `--vessel NAME` is taken
// (FindVessel, simulation/vessel_simulator.h). Keys, units and an example: docs/model.md#
// vessel-files.
#pragma once

#include <string>
#include <vector>

#include "simulation/vessel_simulator.h"

namespace usvid {

struct VesselFile {
  std::string name;            // the file's "name", else its stem
  std::vector<double> params;  // Mmg's parameters, in Mmg::kParamNames order
  double length_m = 0.0;
  // The controls: limits, the neutral and cruise inputs, the rudder's sign and rate. The
  // registry fills in the rest from the vessel type (simulation/vessel_registry.cc).
  Actuation actuation;
  // One line for each coefficient estimated rather than given, and each warning (a particular
  // outside the range its formula was fitted on).
  std::vector<std::string> estimated;
  std::vector<std::string> warnings;
  bool wind_body = false;  // the file has a wind section (VesselInfo::wind_body)
};

// Throws InputError "file:line: key: what" for a file that cannot be read, a syntax error, a
// missing particular, an unknown key, or a value out of its physical range.
VesselFile ReadVesselFile(const std::string& path);

}  // namespace usvid
