#include "apps/usvid/data_file.h"

#include <cstdio>
#include <filesystem>

#include "core/csv_dataset.h"

namespace usvid {

Dataset ReadDataFile(const std::string& path, const std::string& command) {
  constexpr std::uintmax_t kLongFile = 16u << 20;
  CsvReadOptions options;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size >= kLongFile) {
    options.progress = [&](double fraction, Eigen::Index rows) {
      std::fprintf(stderr, "%s: reading %s: %3.0f %% (%ld rows)\n", command.c_str(), path.c_str(),
                   100.0 * fraction, static_cast<long>(rows));
    };
  }
  Dataset data = ReadDatasetCsv(path, options);
  for (const Dataset::TextColumn& c : data.text_columns())
    std::fprintf(stderr, "%s: note: column '%s' is text ('%s' at %s), kept aside and not used\n",
                 command.c_str(), c.name.c_str(), c.text.c_str(), c.where.c_str());
  return data;
}

}  // namespace usvid
