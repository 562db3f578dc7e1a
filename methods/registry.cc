#include "methods/registry.h"

#include <algorithm>

#include "core/error.h"

namespace usvid {

#define USVID_METHOD(factory) Method factory();
#include "methods/method_list.h"
#undef USVID_METHOD

const std::vector<Method>& Methods() {
  static const std::vector<Method> methods = {
#define USVID_METHOD(factory) factory(),
#include "methods/method_list.h"
#undef USVID_METHOD
  };
  return methods;
}

const Method& FindMethod(std::string_view name) {
  const auto& all = Methods();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Method& m) { return m.name == name; });
  if (it == all.end())
    throw InputError("--method '" + std::string(name) + "': unknown method (known: " +
                     MethodNames() + ")");
  return *it;
}

std::string MethodNames() {
  std::string names;
  for (const Method& m : Methods()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

}  // namespace usvid
