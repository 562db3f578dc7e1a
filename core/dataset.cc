#include "core/dataset.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <limits>
#include <utility>

#include "core/check.h"
#include "core/error.h"
#include "core/nan.h"

namespace usvid {

namespace {

// A channel sampled on at most this share of its rows is stored sparse.
constexpr Eigen::Index kSparseShareDenominator = 4;

}  // namespace

Channel::Channel(std::string name_in, Eigen::VectorXd values, Mask sampled)
    : name(std::move(name_in)), size_(values.size()) {
  USVID_CHECK(sampled.size() == values.size(), "a sampled flag per value");
  count_ = sampled.count();
  const bool sparse = count_ * kSparseShareDenominator <= size_ && size_ > 0 &&
                      size_ <= std::numeric_limits<std::int32_t>::max();
  dense_ = std::make_shared<DenseForm>();
  if (sparse) {
    auto form = std::make_shared<SparseForm>();
    form->rows.reserve(static_cast<std::size_t>(count_));
    form->samples.resize(count_);
    for (Eigen::Index k = 0, i = 0; k < size_; ++k)
      if (sampled(k)) {
        form->rows.push_back(static_cast<std::int32_t>(k));
        form->samples(i++) = values(k);
      }
    sparse_ = std::move(form);
    return;
  }
  for (Eigen::Index k = 0; k < size_; ++k)
    if (!sampled(k)) values(k) = kNaN;
  dense_->values = std::move(values);
  dense_->sampled = std::move(sampled);
}

Channel Channel::FromSamples(std::string name, Eigen::Index rows,
                             std::vector<std::int32_t> sample_rows, Eigen::VectorXd samples) {
  USVID_CHECK(static_cast<Eigen::Index>(sample_rows.size()) == samples.size(),
              "a value per sampled row");
  USVID_CHECK(std::ranges::is_sorted(sample_rows) &&
                  std::ranges::adjacent_find(sample_rows) == sample_rows.end() &&
                  (sample_rows.empty() || (sample_rows.front() >= 0 && sample_rows.back() < rows)),
              "sampled rows ascending, within the rows");
  const auto count = static_cast<Eigen::Index>(sample_rows.size());
  Channel c;
  c.name = std::move(name);
  c.size_ = rows;
  c.count_ = count;
  c.dense_ = std::make_shared<DenseForm>();
  auto form = std::make_shared<SparseForm>();
  form->rows = std::move(sample_rows);
  form->samples = std::move(samples);
  c.sparse_ = std::move(form);
  // Too many samples to hold sparse: the dense form, built as for any sparse channel.
  if (count * kSparseShareDenominator > rows || rows > std::numeric_limits<std::int32_t>::max())
    return Channel(c.name, c.values(), c.sampled());
  return c;
}

bool Channel::IsSampled(Eigen::Index row) const {
  if (!sparse_) return dense_->sampled(row);
  return std::ranges::binary_search(sparse_->rows, static_cast<std::int32_t>(row));
}

double Channel::Value(Eigen::Index row) const {
  if (!sparse_) return dense_->values(row);
  const auto it = std::ranges::lower_bound(sparse_->rows, static_cast<std::int32_t>(row));
  if (it == sparse_->rows.end() || *it != row) return kNaN;
  return sparse_->samples(it - sparse_->rows.begin());
}

const Channel::DenseForm& Channel::Dense() const {
  if (sparse_) {
    std::call_once(dense_->built, [this] {
      Eigen::VectorXd values = Eigen::VectorXd::Constant(size_, kNaN);
      Mask sampled = Mask::Constant(size_, false);
      ForEachSample([&](Eigen::Index k, double v) {
        values(k) = v;
        sampled(k) = true;
      });
      dense_->values = std::move(values);
      dense_->sampled = std::move(sampled);
    });
  }
  return *dense_;
}

std::size_t Channel::StorageBytes() const {
  std::size_t bytes = static_cast<std::size_t>(dense_->values.size()) * sizeof(double) +
                      static_cast<std::size_t>(dense_->sampled.size()) * sizeof(bool);
  if (sparse_)
    bytes += sparse_->rows.size() * sizeof(std::int32_t) +
             static_cast<std::size_t>(sparse_->samples.size()) * sizeof(double);
  return bytes;
}

Channel Channel::Segment(Eigen::Index first, Eigen::Index count) const {
  USVID_CHECK(first >= 0 && count >= 0 && first + count <= size_, "rows within the channel");
  if (!sparse_)
    return Channel(name, dense_->values.segment(first, count),
                   dense_->sampled.segment(first, count));
  const auto& rows = sparse_->rows;
  const auto lo = std::ranges::lower_bound(rows, static_cast<std::int32_t>(first));
  const auto hi = std::ranges::lower_bound(rows, static_cast<std::int32_t>(first + count));
  std::vector<std::int32_t> kept;
  kept.reserve(static_cast<std::size_t>(hi - lo));
  for (auto it = lo; it != hi; ++it) kept.push_back(static_cast<std::int32_t>(*it - first));
  return FromSamples(name, count, std::move(kept),
                     sparse_->samples.segment(lo - rows.begin(), hi - lo));
}

Channel Channel::Select(const std::vector<Eigen::Index>& rows) const {
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (!sparse_) {
    Eigen::VectorXd v(n);
    Mask s(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      v(k) = dense_->values(rows[static_cast<std::size_t>(k)]);
      s(k) = dense_->sampled(rows[static_cast<std::size_t>(k)]);
    }
    return Channel(name, std::move(v), std::move(s));
  }
  std::vector<std::int32_t> kept;
  std::vector<double> values;
  auto it = sparse_->rows.begin();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index row = rows[static_cast<std::size_t>(k)];
    it = std::lower_bound(it, sparse_->rows.end(), static_cast<std::int32_t>(row));
    if (it != sparse_->rows.end() && *it == row) {
      kept.push_back(static_cast<std::int32_t>(k));
      values.push_back(sparse_->samples(it - sparse_->rows.begin()));
    }
  }
  return FromSamples(
      name, n, std::move(kept),
      Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size())));
}

const Channel* Dataset::Find(const std::string& name) const {
  for (const Channel& c : channels_)
    if (c.name == name) return &c;
  return nullptr;
}

Channel* Dataset::FindMutable(const std::string& name) {
  return const_cast<Channel*>(std::as_const(*this).Find(name));
}

const Channel& Dataset::Get(const std::string& name) const {
  const Channel* c = Find(name);
  if (c == nullptr) {
    CheckNotText(name);
    throw InputError("no channel '" + name + "' in the data");
  }
  return *c;
}

void Dataset::Set(const std::string& name, Eigen::VectorXd values) {
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled =
      Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(values.size(), true);
  Set(name, std::move(values), std::move(sampled));
}

void Dataset::Set(const std::string& name, Eigen::VectorXd values,
                  Eigen::Array<bool, Eigen::Dynamic, 1> sampled) {
  USVID_CHECK(values.size() == rows() && sampled.size() == rows(), "a channel as long as t");
  Set(Channel(name, std::move(values), std::move(sampled)));
}

void Dataset::Set(Channel channel) {
  USVID_CHECK(channel.size() == rows(), "a channel as long as t");
  std::erase_if(text_columns_, [&](const TextColumn& c) { return c.name == channel.name; });
  if (Channel* c = FindMutable(channel.name)) {
    *c = std::move(channel);
  } else {
    channels_.push_back(std::move(channel));
  }
}

void Dataset::Remove(const std::string& name) {
  std::erase_if(channels_, [&](const Channel& c) { return c.name == name; });
}

void Dataset::KeepRows(const std::vector<bool>& keep) {
  USVID_CHECK(static_cast<Eigen::Index>(keep.size()) == rows(), "a keep flag per row");
  std::vector<Eigen::Index> idx;
  for (Eigen::Index i = 0; i < rows(); ++i)
    if (keep[i]) idx.push_back(i);
  const auto n = static_cast<Eigen::Index>(idx.size());
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = t_(idx[k]);
  t_ = std::move(t);
  for (Channel& c : channels_) c = c.Select(idx);
}

Dataset Dataset::Rows(Eigen::Index first, Eigen::Index count) const {
  USVID_CHECK(first >= 0 && count >= 0 && first + count <= rows(), "rows within the record");
  Dataset out(t_.segment(first, count));
  out.metadata_ = metadata_;
  out.text_columns_ = text_columns_;
  for (const Channel& c : channels_) out.channels_.push_back(c.Segment(first, count));
  return out;
}

void Dataset::SetTime(Eigen::VectorXd t) {
  USVID_CHECK(t.size() == rows() || channels_.empty(), "a time base as long as the channels");
  t_ = std::move(t);
}

std::string Dataset::TextColumn::Error() const {
  return where + ": column '" + name + "': '" + text + "' is not a number";
}

void Dataset::AddTextColumn(TextColumn column) { text_columns_.push_back(std::move(column)); }

void Dataset::CheckNotText(const std::string& name) const {
  for (const TextColumn& c : text_columns_)
    if (c.name == name) throw InputError(c.Error());
}

std::string Dataset::Source() const {
  const auto it = metadata_.find("source");
  return it != metadata_.end() ? it->second : "";
}

std::string Dataset::SourcePrefix() const {
  const std::string source = Source();
  return source.empty() ? "" : source + ": ";
}

double MedianInterval(const Eigen::Ref<const Eigen::VectorXd>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> dt(static_cast<size_t>(t.size() - 1));
  for (Eigen::Index i = 1; i < t.size(); ++i) dt[static_cast<size_t>(i - 1)] = t(i) - t(i - 1);
  std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
  return dt[dt.size() / 2];
}

}  // namespace usvid
