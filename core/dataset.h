// A time series: strictly increasing time t [s] and named channels (SI units, radians).
// Multi-rate logs leave samples out: each channel has a "sampled" mask, and a value that was
// not sampled reads as NaN so that a forgotten mask check shows up instead of a silent zero.
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace usvid {

struct Channel {
  std::string name;
  Eigen::VectorXd values;  // NaN where not sampled
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled;

  bool FullySampled() const { return sampled.all(); }
};

class Dataset {
 public:
  Dataset() = default;
  explicit Dataset(Eigen::VectorXd t) : t_(std::move(t)) {}

  const Eigen::VectorXd& t() const { return t_; }
  Eigen::Index rows() const { return t_.size(); }
  double duration() const { return rows() > 0 ? t_(rows() - 1) - t_(0) : 0.0; }

  const std::vector<Channel>& channels() const { return channels_; }
  bool Has(const std::string& name) const { return Find(name) != nullptr; }
  const Channel* Find(const std::string& name) const;
  // Throws InputError naming the missing channel, or, for a text column, the file:line:column of
  // its first text.
  const Channel& Get(const std::string& name) const;
  const Eigen::VectorXd& operator[](const std::string& name) const { return Get(name).values; }

  // Adds or replaces a fully sampled channel (values.size() must equal rows()).
  void Set(const std::string& name, Eigen::VectorXd values);
  // Adds or replaces a channel with its mask; values where !sampled become NaN.
  void Set(const std::string& name, Eigen::VectorXd values,
           Eigen::Array<bool, Eigen::Dynamic, 1> sampled);
  void Remove(const std::string& name);
  // Keeps the rows where keep(i) is true, in every channel.
  void KeepRows(const std::vector<bool>& keep);
  // A copy of `count` rows from `first` (every channel, the metadata): a window of a long record
  // in time proportional to the window, not the record.
  Dataset Rows(Eigen::Index first, Eigen::Index count) const;
  void SetTime(Eigen::VectorXd t);

  // Columns of the file that held text where a number was expected first (a mode, a comment):
  // kept aside by name with the located error a command that needs one as a number throws.
  struct TextColumn {
    std::string name;
    std::string where;  // "file:line:column" of its first text
    std::string text;   // that text
    // "file:line:column: column 'NAME': 'text' is not a number"
    std::string Error() const;
  };
  void AddTextColumn(TextColumn column);
  const std::vector<TextColumn>& text_columns() const { return text_columns_; }
  // Throws the text column's InputError when `name` is one; for the checks that say themselves
  // what is missing ("no channel 'x' for ...") before they do.
  void CheckNotText(const std::string& name) const;

  // The file the data came from (metadata "source"), or ""; SourcePrefix is "FILE: " or "", to
  // start an error message about the data with.
  std::string Source() const;
  std::string SourcePrefix() const;

  std::map<std::string, std::string>& metadata() { return metadata_; }
  const std::map<std::string, std::string>& metadata() const { return metadata_; }

 private:
  Channel* FindMutable(const std::string& name);

  Eigen::VectorXd t_;
  std::vector<Channel> channels_;
  std::vector<TextColumn> text_columns_;
  std::map<std::string, std::string> metadata_;
};

// The median interval between consecutive times [s] (0 for fewer than two).
double MedianInterval(const Eigen::Ref<const Eigen::VectorXd>& t);

}  // namespace usvid
