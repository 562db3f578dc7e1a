// JSON files (truth, model, metrics, suites) through nlohmann-json. Reading reports syntax
// errors as "file:line:column: what"; writing is atomic and pretty-printed.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace usvid {

// Files people write (suites) may carry // and /* */ comments, as the embedded suites do; files
// usvid writes and reads back (model, truth, metrics) are plain JSON.
enum class JsonComments { kRefused, kAllowed };

nlohmann::json ReadJsonFile(const std::string& path,
                            JsonComments comments = JsonComments::kRefused);
nlohmann::json ParseJson(const std::string& text, const std::string& file,
                         JsonComments comments = JsonComments::kRefused);
void WriteJsonFile(const std::string& path, const nlohmann::json& value);

}  // namespace usvid
