#include "harness/embedded_suites.h"

#include <stdexcept>

#include "harness/embedded_files.h"
#include "harness/smoke_suite.h"

namespace usvid {

namespace {

// The default (harness/suites/default.json): odin3dof and odin-hs; trained on zig-zag, random
// steps and the step grid, tested on zig-zag, step grid and random steps; nominal, gp, sindy,
// fossen-ceres and eb-lr; two noise levels; four seeds. Quick (quick.json): the same vessels,
// maneuvers and methods with one noise level, one seed, shorter records and a smaller GP search.
// Realistic (realistic.json, docs/compare.md#realistic): the default suite's vessels under an
// unmeasured current and gusty wind, waves, a gyro bias, saturated actuators, an IMU at 50 Hz and
// a GPS at 5 Hz with dropouts, trained under a heading autopilot; realistic-measured the same
// records with the wind and the current logged, and the equation methods reading them.
constexpr EmbeddedSuite kEmbeddedSuites[] = {
    {"default", "harness/suites/default.json", "harness/suites/quick.json", "the default"},
    {"quick", "harness/suites/quick.json", "harness/suites/quick.json",
     "the default suite, smaller: seconds, not minutes"},
    {"realistic", "harness/suites/realistic.json", "", "the sea and sensors of a real trial"},
    {"realistic-measured", "harness/suites/realistic-measured.json", "",
     "the same with the wind and the current logged"},
    {"eb2dof", "harness/suites/eb2dof.json", "", "Eriksen & Breivik's vessel on their step grid"},
    {"real", "", "", "the measured data of --data-dir"},
};

}  // namespace

std::span<const EmbeddedSuite> EmbeddedSuites() { return kEmbeddedSuites; }

const EmbeddedSuite* FindEmbeddedSuite(std::string_view name) {
  for (const EmbeddedSuite& s : kEmbeddedSuites)
    if (s.name == name) return &s;
  return nullptr;
}

std::string EmbeddedSuiteNames() {
  std::string names;
  for (const EmbeddedSuite& s : kEmbeddedSuites)
    names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names;
}

std::string EmbeddedSuitesHelp() {
  std::string help;
  for (const EmbeddedSuite& s : kEmbeddedSuites)
    help += (help.empty() ? "" : ", ") + std::string(s.name) + " (" + std::string(s.about) + ")";
  return help;
}

bool IsSuiteName(const std::string& suite) {
  return suite.find('/') == std::string::npos && suite.find('.') == std::string::npos;
}

Suite LoadEmbeddedSuite(const EmbeddedSuite& suite, bool quick) {
  if (suite.file.empty())
    throw std::logic_error("embedded suite " + std::string(suite.name) +
                           " is made from measured data (harness/real_suite.h)");
  const std::string_view file = quick && !suite.quick_file.empty() ? suite.quick_file : suite.file;
  Suite parsed = ParseSuite(nlohmann::json::parse(EmbeddedText(file), nullptr, true,
                                                  /*ignore_comments=*/true),
                            std::string(file) + " (embedded)");
  return quick && suite.quick_file.empty() ? SmokeVariant(std::move(parsed)) : parsed;
}

Suite LoadEmbeddedSuite(std::string_view name, bool quick) {
  const EmbeddedSuite* suite = FindEmbeddedSuite(name);
  if (suite == nullptr) throw std::logic_error("no embedded suite " + std::string(name));
  return LoadEmbeddedSuite(*suite, quick);
}

std::string_view EmbeddedText(std::string_view path) {
  for (const EmbeddedFile& f : kEmbeddedFiles)
    if (f.path == path) return f.text;
  throw std::logic_error("harness/CMakeLists.txt embeds no file " + std::string(path));
}

}  // namespace usvid
