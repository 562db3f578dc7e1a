#include "simulation/vessel_ref.h"

#include <utility>

#include "core/check.h"

namespace usvid {

VesselRef::VesselRef(std::string name) : name_(std::move(name)) {
  if (!name_.empty()) simulator_ = &FindVessel(name_);
}

const VesselSimulator& VesselRef::Simulator() const {
  USVID_CHECK(simulator_ != nullptr, "a vessel asked of an empty VesselRef");
  return *simulator_;
}

}  // namespace usvid
