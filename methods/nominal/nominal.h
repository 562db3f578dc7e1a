// `nominal`: the vessel as it is (its defaults, or --params), nothing fitted: the physics-based
// prediction every identified model has to beat, and the ceiling of a comparison's verdict.
#pragma once

#include <string_view>

namespace usvid {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kNominalMethodName = "nominal";

}  // namespace usvid
