#include "core/records.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace usvid {

Dataset JoinRecords(std::vector<Dataset> records, std::vector<std::string>* dropped) {
  if (records.empty()) throw InputError("no records to join");
  if (records.size() == 1) return std::move(records.front());
  std::vector<std::string> kept;
  for (const Channel& c : records.front().channels()) {
    const bool everywhere =
        std::ranges::all_of(records, [&](const Dataset& d) { return d.Has(c.name); });
    if (everywhere) kept.push_back(c.name);
  }
  if (dropped)
    for (const Dataset& d : records)
      for (const Channel& c : d.channels())
        if (std::ranges::find(kept, c.name) == kept.end() &&
            std::ranges::find(*dropped, c.name) == dropped->end())
          dropped->push_back(c.name);

  Eigen::Index rows = 0;
  for (const Dataset& d : records) rows += d.rows();
  Eigen::VectorXd t(rows);
  std::vector<Eigen::VectorXd> values(kept.size(), Eigen::VectorXd(rows));
  std::vector<Eigen::Array<bool, Eigen::Dynamic, 1>> sampled(
      kept.size(), Eigen::Array<bool, Eigen::Dynamic, 1>(rows));
  Eigen::Index at = 0;
  double end = 0.0;
  std::string sources;
  for (size_t r = 0; r < records.size(); ++r) {
    const Dataset& d = records[r];
    if (d.rows() == 0) continue;
    const double shift = at == 0 ? 0.0 : end + kRecordGapS - d.t()(0);
    t.segment(at, d.rows()) = d.t().array() + shift;
    end = t(at + d.rows() - 1);
    for (size_t c = 0; c < kept.size(); ++c) {
      const Channel& channel = d.Get(kept[c]);
      values[c].segment(at, d.rows()) = channel.values();
      sampled[c].segment(at, d.rows()) = channel.sampled();
    }
    at += d.rows();
    sources += (sources.empty() ? "" : ", ") +
               (d.Source().empty() ? "record " + std::to_string(r + 1) : d.Source());
  }
  Dataset out(std::move(t));
  for (size_t c = 0; c < kept.size(); ++c)
    out.Set(kept[c], std::move(values[c]), std::move(sampled[c]));
  for (const Dataset& d : records)
    for (const Dataset::TextColumn& text : d.text_columns())
      if (std::ranges::none_of(out.text_columns(),
                               [&](const Dataset::TextColumn& o) { return o.name == text.name; }))
        out.AddTextColumn(text);
  out.metadata() = records.front().metadata();
  out.metadata().erase("maneuver");  // each record's, not the joined one's
  out.metadata()["records"] = std::to_string(records.size());
  out.metadata()["source"] = sources;
  return out;
}

std::vector<long> RecordStarts(const Eigen::Ref<const Eigen::VectorXd>& t) {
  std::vector<long> starts;
  if (t.size() > 0) starts.push_back(0);
  for (Eigen::Index i = 1; i < t.size(); ++i)
    if (t(i) - t(i - 1) >= 0.5 * kRecordGapS) starts.push_back(static_cast<long>(i));
  return starts;
}

RecordSplit SplitEachRecord(const Dataset& data, double last_share, long min_rows,
                            const std::string& what) {
  const std::vector<long> starts = RecordStarts(data.t());
  if (starts.empty()) throw InputError(data.SourcePrefix() + what + ": no rows");
  std::vector<Dataset> first, last;
  for (size_t k = 0; k < starts.size(); ++k) {
    const long begin = starts[k];
    const long end = k + 1 < starts.size() ? starts[k + 1] : static_cast<long>(data.rows());
    const long split =
        begin +
        static_cast<long>(std::floor((1.0 - last_share) * static_cast<double>(end - begin)));
    if (split - begin < min_rows || end - split < min_rows)
      throw InputError(data.SourcePrefix() + what + ": too few rows to hold out a part of record " +
                       std::to_string(k + 1) + " of " + std::to_string(starts.size()) + " (" +
                       std::to_string(end - begin) + ")");
    first.push_back(data.Rows(begin, split - begin));
    last.push_back(data.Rows(split, end - split));
  }
  RecordSplit out{JoinRecords(std::move(first)), JoinRecords(std::move(last))};
  out.first.metadata() = out.last.metadata() = data.metadata();
  return out;
}

std::vector<std::string> RecordList(const std::string& text, const std::string& what) {
  std::vector<std::string> names;
  size_t from = 0;
  while (true) {
    const size_t comma = text.find(',', from);
    names.push_back(
        text.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (names.back().empty()) throw InputError(what + ": an empty file name in '" + text + "'");
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return names;
}

}  // namespace usvid
