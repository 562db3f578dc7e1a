// Each subcommand of `usvid` registers itself on the application: its options, its help and
// the callback that runs it. A callback throws InputError for bad input (main: exit code 2).
#pragma once

#include <CLI/CLI.hpp>

namespace usvid {

void AddImportCommand(CLI::App& app);
void AddInfoCommand(CLI::App& app);
void AddSimulateCommand(CLI::App& app);
void AddVesselCommand(CLI::App& app);
void AddPreprocessCommand(CLI::App& app);
void AddActuatorsCommand(CLI::App& app);
void AddIdentifyCommand(CLI::App& app);
void AddMethodsCommand(CLI::App& app);
void AddEvaluateCommand(CLI::App& app);
void AddCompareCommand(CLI::App& app);
void AddDiagnoseCommand(CLI::App& app);
void AddDesignCommand(CLI::App& app);
void AddInitTrackCommand(CLI::App& app);

}  // namespace usvid
