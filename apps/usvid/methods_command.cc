// usvid methods [--markdown]: every identification method with its options, as each declares
// them (methods/method_options.h). --markdown prints docs/options.md.

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "harness/options_reference.h"
#include "methods/registry.h"

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
    for (const Method& m : Methods()) {
      std::cout << m.name << ": " << m.summary << '\n';
      for (const OptionSpec& s : m.options)
        std::cout << "  " << s.key << " (" << s.Flag() << "): " << s.AllowedValues()
                  << "; default " << (s.type == OptionType::kFlag ? "false" : s.DefaultText())
                  << '\n';
    }
  });
}

}  // namespace usvid
