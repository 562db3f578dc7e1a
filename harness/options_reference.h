// docs/options.md, made from the declarations themselves (methods/method_options.h): every
// method a suite may list (harness/suite_methods.h), and the keys every method entry shares.
// `usvid methods --markdown` prints it; tests/apps/options_cli_test.cc fails when the committed
// page differs.
#pragma once

#include <string>

namespace usvid {

std::string OptionsReferenceMarkdown();

}  // namespace usvid
