// The typed refit of one vessel type, declared for refit.cc's dispatch by name. typed_refit.h
// defines it; each vessel's instance compiles in a translation unit of its own, generated from
// refit_vessel.cc.in for every vessel type (methods/CMakeLists.txt), so that the five Jet
// instantiations build in parallel and no file that dispatches compiles one.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/refit/refit.h"
#include "simulation/vessel_simulator.h"

namespace usvid::refit {

template <Vessel V>
RefitResult RefitTyped(const VesselInfo& info, const Dataset& data,
                       const std::vector<double>& start, const RefitOptions& o);

template <Vessel V>
std::map<std::string, Eigen::VectorXd> DerivativeResidualTyped(const VesselInfo& info,
                                                               const Dataset& data,
                                                               const std::vector<double>& params);

}  // namespace usvid::refit
