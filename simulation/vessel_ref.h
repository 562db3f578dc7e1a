// A vessel resolved once, where its name enters (a command's --vessel, a suite's vessels, a
// fit's request), and passed down: the name or file it was given, and the simulator behind it.
// A compiled-in vessel or a vessel file (FindVessel, simulation/vessel_simulator.h); a file is
// read on the first resolution and kept.
#pragma once

#include <string>

#include "simulation/vessel_simulator.h"

namespace usvid {

class VesselRef {
 public:
  // No vessel: a fit on channels named by hand.
  VesselRef() = default;
  // Resolves `name` now: an empty name is no vessel; an unknown name or a faulty file throws
  // InputError as FindVessel does. Implicit, as a name is where a vessel is asked for.
  VesselRef(std::string name);  // NOLINT(google-explicit-constructor)
  VesselRef(const char* name) : VesselRef(std::string(name)) {}  // NOLINT

  bool empty() const { return simulator_ == nullptr; }
  // The name or the file's path as given: model.json's "vessel", a result row's.
  const std::string& Name() const { return name_; }
  // The vessel's description and simulator; checked: not on an empty reference.
  const VesselInfo& Info() const { return Simulator().Info(); }
  const VesselSimulator& Simulator() const;
  // The same vessel: the same name or path.
  friend bool operator==(const VesselRef& a, const VesselRef& b) { return a.name_ == b.name_; }

 private:
  std::string name_;
  const VesselSimulator* simulator_ = nullptr;
};

}  // namespace usvid
