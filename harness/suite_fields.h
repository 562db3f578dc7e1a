// The fields of a suite file (harness/suite.h), each declared once: its key, the suites it
// applies to, whether it must be given, its default, what it holds, and the one function that
// reads it and the one that writes it back. ParseSuite refuses a key not declared here, reads
// every declared key through it in this order, and SuiteToJson writes the suite back through it,
// so reading, writing, defaults and docs/suites.md (`usvid compare --fields`) come from one list.
// (Drake's Serialize, one visit per field for reading and writing, is the model.)
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace usvid {

struct Suite;

// Which suites a field applies to, or must be given in: none, every suite, simulated ones
// (maneuvers simulated on the suite's vessels) or suites on measured data ("data").
enum class SuiteKind { kNone, kAny, kSimulated, kMeasured };

// What a field's reader is told besides its value.
struct SuiteFieldContext {
  std::string file;  // the suite's, which every error names first
  std::string key;
  bool measured = false;  // the suite has "data"
};

struct SuiteField {
  std::string_view key;
  SuiteKind applies = SuiteKind::kAny;
  SuiteKind required = SuiteKind::kNone;  // the suites that must give it
  std::string_view default_text;          // when not given
  std::string_view what;
  // The message after "FILE: " when the field is given to a suite it does not apply to.
  std::string_view elsewhere;
  // Reads the field's value into `s`. The fields before it in SuiteFields() are read.
  void (*read)(const nlohmann::json& value, const SuiteFieldContext& c, Suite& s);
  // The value to write back; null when there is none to write (an optional field left empty is
  // not written, so a suite echoes, and its cells resume, as it was given).
  nlohmann::json (*write)(const Suite& s);
  bool AppliesTo(bool measured) const { return Includes(applies, measured); }
  bool RequiredIn(bool measured) const { return Includes(required, measured); }
  static bool Includes(SuiteKind kind, bool measured) {
    return kind == SuiteKind::kAny ||
           (kind != SuiteKind::kNone && (kind == SuiteKind::kMeasured) == measured);
  }
};

// Every field, in the order ParseSuite reads them: those a field reads from come first.
const std::vector<SuiteField>& SuiteFields();

// docs/suites.md: a table of the fields, generated (`usvid compare --fields`).
std::string SuiteFieldsMarkdown();

}  // namespace usvid
