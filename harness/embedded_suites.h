// The embedded suites, one row each (`usvid compare --suite NAME`; docs/compare.md): the name, the
// JSON it is read from, what --quick makes of it and the line --help gives. Adding one is a JSON
// file in harness/suites/ (harness/CMakeLists.txt compiles in every file there) and a row in
// kEmbeddedSuites (embedded_suites.cc); docs/architecture.md#adding-an-embedded-suite shows it.
// The real suite is a row too, its tracks made from the files of a data folder
// (harness/real_suite.h); the files it embeds (its track files, vessel files) are read here by
// their path in the repository.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "harness/suite.h"

namespace usvid {

struct EmbeddedSuite {
  std::string_view name;
  // Its JSON, by its path in the repository; "" for the real suite, made from measured data.
  std::string_view file;
  // With --quick: this suite instead (a smaller one of its own), or "" for the suite's
  // seconds-long variant (harness/smoke_suite.h).
  std::string_view quick_file;
  std::string_view about;  // for --help, after the name
};

std::span<const EmbeddedSuite> EmbeddedSuites();

// The row named `name`; nullptr for none.
const EmbeddedSuite* FindEmbeddedSuite(std::string_view name);

// "default, quick, ...", in the table's order.
std::string EmbeddedSuiteNames();

// The embedded suites for --suite's help: "default (the default), quick (...), ...".
std::string EmbeddedSuitesHelp();

// Whether `suite` names an embedded suite rather than a file: no '/' and no '.' in it.
bool IsSuiteName(const std::string& suite);

// A simulated embedded suite, parsed; `quick` as its row says. Throws std::logic_error for the
// real suite (harness/real_suite.h makes its tracks).
Suite LoadEmbeddedSuite(const EmbeddedSuite& suite, bool quick = false);
// The same by name; throws std::logic_error for a name no row has.
Suite LoadEmbeddedSuite(std::string_view name, bool quick = false);

// The text of an embedded file, by its path in the repository ("harness/tracks/kvlcc2.yaml").
// Throws std::logic_error for a path that is not embedded: a fault of the build, not of input.
std::string_view EmbeddedText(std::string_view path);

}  // namespace usvid
