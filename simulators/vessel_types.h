// Every vessel type, once. The typed code of the refit (methods/refit) and of the diagnosis's
// effect fitters (diagnosis/) is dispatched by name here, and CMake compiles each vessel's
// instance in a translation unit of its own, one per entry of USVID_VESSEL_TYPES
// (usvid_per_vessel_sources, cmake/UsvidHelpers.cmake: it reads the list below). A new vessel is
// its header, one entry in USVID_VESSEL_TYPES, and its actuation in simulation/vessel_registry.cc.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "simulators/eb2dof.h"
#include "simulators/kvlcc2.h"
#include "simulators/mmg.h"
#include "simulators/msd.h"
#include "simulators/odin3dof.h"
#include "simulators/odin_hs.h"

// X(Type) for every vessel type.
#define USVID_VESSEL_TYPES(X) X(Msd) X(Odin3Dof) X(Eb2Dof) X(OdinHs) X(Kvlcc2) X(Mmg)

namespace usvid {

#define USVID_VESSEL_TYPE_ENTRY(V) , V
using VesselTypes = std::tuple<void USVID_VESSEL_TYPES(USVID_VESSEL_TYPE_ENTRY)>;
#undef USVID_VESSEL_TYPE_ENTRY

inline constexpr std::size_t kVesselTypeCount = std::tuple_size_v<VesselTypes> - 1;

// The I-th vessel type of the list (0-based).
template <std::size_t I>
using VesselTypeAt = std::tuple_element_t<I + 1, VesselTypes>;

// f.template operator()<V>() for the vessel type V whose kName is `name`; nullopt when no
// vessel type has that name.
template <typename F>
auto WithVesselType(std::string_view name, F&& f)
    -> std::optional<decltype(f.template operator()<VesselTypeAt<0>>())> {
  using R = decltype(f.template operator()<VesselTypeAt<0>>());
  std::optional<R> out;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((VesselTypeAt<I>::kName == name ? (void)out.emplace(f.template operator()<VesselTypeAt<I>>())
                                     : (void)0),
     ...);
  }(std::make_index_sequence<kVesselTypeCount>{});
  return out;
}

}  // namespace usvid
