// JSON files (truth, model, metrics, suites) through nlohmann-json. Reading reports syntax
// errors as "file:line:column: what"; writing is atomic and pretty-printed.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace usvid {

nlohmann::json ReadJsonFile(const std::string& path);
nlohmann::json ParseJson(const std::string& text, const std::string& file);
void WriteJsonFile(const std::string& path, const nlohmann::json& value);

}  // namespace usvid
