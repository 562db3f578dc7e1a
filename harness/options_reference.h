// docs/options.md, made from the declarations themselves (methods/method_options.h): every
// registered method's options, diagnose's, and the keys every suite method entry shares.
// `usvid methods --markdown` prints it; tests/apps/options_cli_test.cc fails when the committed
// page differs.
#pragma once

#include <string>

namespace usvid {

std::string OptionsReferenceMarkdown();

}  // namespace usvid
