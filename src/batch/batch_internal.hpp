// Private: pieces shared by the batch's files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "sphereset/batch.hpp"

namespace sphereset {

// kInvalidArgument when the batch's own options are out of range (format, n, threads).
Status checkBatchOptions(const BatchOptions& options);

namespace detail {

// Folder of the batch's own state inside the output folder: the item records and the run's lock.
inline constexpr const char* kBatchStateFolder = ".sphereset-batch";

// FNV-1a, 64 bits (Fowler, Noll, Vo): a digest to notice changed inputs and outputs, not a
// cryptographic hash.
inline constexpr uint64_t kFnvOffset = 14695981039346656037ull;
inline constexpr uint64_t kFnvPrime = 1099511628211ull;

inline uint64_t fnv1a(std::string_view bytes, uint64_t h = kFnvOffset) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= kFnvPrime;
  }
  return h;
}

// 16 lower-case hex digits.
std::string hex64(uint64_t v);

}  // namespace detail
}  // namespace sphereset
