// Every identification method by name (methods/method_list.h): what identify, compare's suites,
// the design's checks and --help look methods up in.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "methods/method.h"

namespace usvid {

// In registration order.
const std::vector<Method>& Methods();

// Throws InputError naming the unknown method and the known ones.
const Method& FindMethod(std::string_view name);

// "gp, sindy, ...": the names in registration order.
std::string MethodNames();

}  // namespace usvid
