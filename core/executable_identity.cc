#include "core/executable_identity.h"

#include <cstdint>
#include <cstdio>
#include <fstream>

namespace usvid {

std::string ExecutableIdentity() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  if (!in) return "unknown";
  // FNV-1a over the bytes: stable across runs, machines and MPI ranks running the same file.
  uint64_t hash = 14695981039346656037ULL;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ULL;
    }
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

}  // namespace usvid
