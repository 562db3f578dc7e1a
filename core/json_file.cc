#include "core/json_file.h"

#include "core/atomic_file.h"
#include "core/csv_tokenizer.h"
#include "core/error.h"

namespace usvid {

nlohmann::json ParseJson(const std::string& text, const std::string& file, JsonComments comments) {
  try {
    return nlohmann::json::parse(text, nullptr, true, comments == JsonComments::kAllowed);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based position of the offending byte; turn it into line and column.
    const size_t upto = std::min(e.byte > 0 ? e.byte - 1 : 0, text.size());
    int line = 1, column = 1;
    for (size_t i = 0; i < upto; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto colon = what.rfind(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw InputError(Located(file, line, column, "invalid JSON: " + what));
  } catch (const nlohmann::json::exception& e) {
    // Not a syntax error but a value JSON allows and nlohmann cannot hold, such as a number
    // that overflows a double (found by fuzz/suite_fuzzer: 66666e6266).
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    throw InputError(file + ": invalid JSON: " + what);
  }
}

nlohmann::json ReadJsonFile(const std::string& path, JsonComments comments) {
  return ParseJson(ReadTextFile(path), path, comments);
}

void WriteJsonFile(const std::string& path, const nlohmann::json& value) {
  WriteFileAtomically(path, value.dump(2) + "\n");
}

}  // namespace usvid
