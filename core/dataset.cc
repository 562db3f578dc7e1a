#include "core/dataset.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <limits>
#include <utility>

#include "core/check.h"
#include "core/error.h"

namespace usvid {

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
  for (Eigen::Index i = 0; i < rows(); ++i)
    if (!sampled(i)) values(i) = std::numeric_limits<double>::quiet_NaN();
  std::erase_if(text_columns_, [&](const TextColumn& c) { return c.name == name; });
  if (Channel* c = FindMutable(name)) {
    c->values = std::move(values);
    c->sampled = std::move(sampled);
  } else {
    channels_.push_back({name, std::move(values), std::move(sampled)});
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
  for (Channel& c : channels_) {
    Eigen::VectorXd v(n);
    Eigen::Array<bool, Eigen::Dynamic, 1> s(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      v(k) = c.values(idx[k]);
      s(k) = c.sampled(idx[k]);
    }
    c.values = std::move(v);
    c.sampled = std::move(s);
  }
}

Dataset Dataset::Rows(Eigen::Index first, Eigen::Index count) const {
  USVID_CHECK(first >= 0 && count >= 0 && first + count <= rows(), "rows within the record");
  Dataset out(t_.segment(first, count));
  out.metadata_ = metadata_;
  out.text_columns_ = text_columns_;
  for (const Channel& c : channels_)
    out.channels_.push_back({c.name, c.values.segment(first, count), c.sampled.segment(first, count)});
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
