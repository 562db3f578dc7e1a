#include "apps/usvid/data_file.h"

#include <cstdio>
#include <filesystem>

#include "core/csv_dataset.h"
#include "core/derived_channels.h"
#include "core/error.h"
#include "core/records.h"

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

Dataset ReadDataFiles(const std::string& list, const std::string& command,
                      const std::vector<std::string>& required,
                      const std::function<void(Dataset&)>& each) {
  const std::vector<std::string> files = RecordList(list, "--data");
  std::vector<Dataset> records;
  for (const std::string& file : files) {
    records.push_back(ReadDataFile(file, command));
    if (each) each(records.back());
    for (const std::string& channel : required)
      if (!records.back().Has(channel) && !CanDerive(records.back(), channel)) {
        records.back().CheckNotText(channel);
        const std::string from = DerivedFrom(channel);
        throw InputError(file + ": no channel '" + channel + "'" +
                         (from.empty() ? "" : ", nor " + from + " to derive it from") +
                         (files.size() > 1 ? " (every record of --data needs it)" : ""));
      }
  }
  if (records.size() == 1) return std::move(records.front());
  std::vector<std::string> dropped;
  double seconds = 0.0;
  for (const Dataset& d : records) seconds += d.duration();
  Dataset joined = JoinRecords(std::move(records), &dropped);
  std::string names;
  for (const std::string& d : dropped) names += (names.empty() ? "" : ", ") + d;
  std::fprintf(stderr,
               "%s: %zu records, %.1f s in all, fitted jointly; no derivative or "
               "simulation runs from one into the next\n",
               command.c_str(), files.size(), seconds);
  if (!dropped.empty())
    std::fprintf(stderr, "%s: note: channels not in every record, left out: %s\n", command.c_str(),
                 names.c_str());
  return joined;
}

}  // namespace usvid
