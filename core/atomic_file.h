// Results are written whole or not at all: the content goes to a temporary file in the same
// directory, which is then renamed over `path`. On failure nothing is left behind and an
// InputError names the path and the reason (missing directory, a directory, no permission).
#pragma once

#include <string>
#include <string_view>

namespace usvid {

void WriteFileAtomically(const std::string& path, std::string_view content);

// Throws the InputError WriteFileAtomically would for a path that cannot be written (empty, a
// directory, in a missing directory): commands call it before their work, not after.
void CheckOutputFile(const std::string& path);

// Creates `dir` (and its parents) for a command's --out DIR; throws InputError when it exists
// as a file or cannot be created.
void EnsureOutputDirectory(const std::string& dir);

}  // namespace usvid
