// usvid methods [--markdown]: every method a suite may list (harness/suite_methods.h) with its
// options, as each declares them (methods/method_options.h). --markdown prints docs/options.md.

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "harness/options_reference.h"
#include "harness/suite_methods.h"

namespace usvid {

void AddMethodsCommand(CLI::App& app) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("methods", "The identification methods and their options");
  cmd->add_flag("--markdown", *markdown, "The reference page docs/options.md, in full");
  cmd->callback([markdown] {
    if (*markdown) {
      std::cout << OptionsReferenceMarkdown();
      return;
    }
    for (const Method& m : SuiteMethods()) {
      std::cout << m.name << ": " << m.summary << '\n';
      for (const OptionSpec& s : m.options)
        std::cout << "  " << s.key << " (" << s.Flag() << "): " << s.AllowedValues() << "; default "
                  << (s.type == OptionType::kFlag ? "false" : s.DefaultText()) << '\n';
    }
  });
}

}  // namespace usvid
