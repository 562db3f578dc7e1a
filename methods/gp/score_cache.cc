#include "methods/gp/score_cache.h"

#include <bit>
#include <cstdint>

namespace usvid::gp {

size_t ScoreCache::Hash::operator()(const Tree& tree) const {
  uint64_t h = 14695981039346656037ull;  // FNV-1a over each node's fields
  auto mix = [&](uint64_t v) { h = (h ^ v) * 1099511628211ull; };
  for (const Node& n : tree) {
    mix(static_cast<uint64_t>(n.op));
    mix(n.var);
    mix(n.length);
    mix(std::bit_cast<uint64_t>(n.value));
  }
  return static_cast<size_t>(h);
}

// Constants compare by their bits: 0.0 and -0.0 are different trees here.
bool ScoreCache::Equal::operator()(const Tree& a, const Tree& b) const {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].op != b[i].op || a[i].var != b[i].var || a[i].length != b[i].length ||
        std::bit_cast<uint64_t>(a[i].value) != std::bit_cast<uint64_t>(b[i].value))
      return false;
  }
  return true;
}

const Model* ScoreCache::Find(const Tree& tree, int generation) {
  const auto it = entries_.find(tree);
  if (it == entries_.end()) return nullptr;
  it->second.last_bred = generation;
  return &it->second.model;
}

void ScoreCache::Insert(const Tree& tree, const Model& model, int generation) {
  entries_.insert_or_assign(tree, Entry{model, generation});
}

void ScoreCache::Forget(int generation) {
  std::erase_if(entries_,
                [&](const auto& entry) { return entry.second.last_bred < generation - keep_; });
}

}  // namespace usvid::gp
