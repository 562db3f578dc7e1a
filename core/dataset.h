// A time series: strictly increasing time t [s] and named channels (SI units, radians).
// Multi-rate logs leave samples out: each channel knows which rows it sampled, and a value that
// was not sampled reads as NaN so that a forgotten check shows up instead of a silent zero.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace usvid {

// One channel of a Dataset: a value for each row of the record, or none where the channel was
// not sampled. A channel sampled on more than a quarter of the rows is stored dense: a value per
// row (NaN where not sampled) and a flag per row, 9 bytes a row. One sampled on at most a
// quarter (a 1 Hz GPS in a 100 Hz log) is stored sparse: its sampled rows and their values, 12
// bytes a sample (docs/data.md#multi-rate-channels). The accessors that visit samples
// (SampleCount, IsSampled, Value, ForEachSample) read either storage as it is; values() and
// sampled() give the dense form, which a sparse channel builds on first use, once (thread-safe),
// and then holds beside its samples. A channel does not change once made: Dataset::Set replaces
// it, so copies share their storage.
class Channel {
 public:
  using Mask = Eigen::Array<bool, Eigen::Dynamic, 1>;

  // The values of every row, NaN where !sampled; `sampled` as long as `values`.
  Channel(std::string name, Eigen::VectorXd values, Mask sampled);
  // A channel of `rows` rows sampled only on `sample_rows` (ascending, within the rows).
  static Channel FromSamples(std::string name, Eigen::Index rows,
                             std::vector<std::int32_t> sample_rows, Eigen::VectorXd samples);

  std::string name;

  Eigen::Index size() const { return size_; }
  bool Sparse() const { return sparse_ != nullptr; }
  bool FullySampled() const { return SampleCount() == size_; }
  Eigen::Index SampleCount() const { return count_; }
  bool IsSampled(Eigen::Index row) const;
  // The value at `row`, NaN where not sampled.
  double Value(Eigen::Index row) const;
  // f(row, value) for each sampled row, in ascending order.
  template <typename F>
  void ForEachSample(F&& f) const;

  // Dense: a value per row, NaN where not sampled, and the flags.
  const Eigen::VectorXd& values() const { return Dense().values; }
  const Mask& sampled() const { return Dense().sampled; }

  // The bytes its storage holds now (the dense form of a sparse channel included once built).
  std::size_t StorageBytes() const;
  // Rows [first, first + count), and the rows `rows` (ascending), in the storage that suits them.
  Channel Segment(Eigen::Index first, Eigen::Index count) const;
  Channel Select(const std::vector<Eigen::Index>& rows) const;

 private:
  struct DenseForm {
    std::once_flag built;  // a sparse channel's, on first use
    Eigen::VectorXd values;
    Mask sampled;
  };
  struct SparseForm {
    std::vector<std::int32_t> rows;
    Eigen::VectorXd samples;
  };
  Channel() = default;
  const DenseForm& Dense() const;

  Eigen::Index size_ = 0;
  Eigen::Index count_ = 0;
  std::shared_ptr<DenseForm> dense_;          // always; a sparse channel's is empty until built
  std::shared_ptr<const SparseForm> sparse_;  // null for a dense channel
};

template <typename F>
void Channel::ForEachSample(F&& f) const {
  if (sparse_) {
    for (std::size_t i = 0; i < sparse_->rows.size(); ++i)
      f(static_cast<Eigen::Index>(sparse_->rows[i]),
        sparse_->samples(static_cast<Eigen::Index>(i)));
    return;
  }
  for (Eigen::Index k = 0; k < size_; ++k)
    if (dense_->sampled(k)) f(k, dense_->values(k));
}

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
  const Eigen::VectorXd& operator[](const std::string& name) const { return Get(name).values(); }

  // Adds or replaces a fully sampled channel (values.size() must equal rows()).
  void Set(const std::string& name, Eigen::VectorXd values);
  // Adds or replaces a channel with its mask; values where !sampled become NaN.
  void Set(const std::string& name, Eigen::VectorXd values,
           Eigen::Array<bool, Eigen::Dynamic, 1> sampled);
  // Adds or replaces the channel of its name (as long as t).
  void Set(Channel channel);
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
