// Private: a memo of recent outside-volume queries, keyed by the exact bits of the ball.
//
// The fit asks for the same ball again and again: a sphere update whose cluster lost or gained
// only points that do not set its radius starts where the last one did and retraces it; a
// teleport's split, the energy of the best state and the bound re-evaluate balls computed
// before. Measured on the armadillo at n = 64: 22% of the fit's 136 702 queries repeat an
// earlier ball exactly (29% of the sphere updates', 26% of the teleports'). The query is a
// deterministic function of the ball, so an answer from the memo is the answer the query
// would give, bit for bit: results do not depend on what the memo holds, on its size or on
// the threads. It is direct-mapped (a newer ball evicts an older one of the same slot) in
// shards with a lock each, and allocated on the first query.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

class SovMemo {
 public:
  // Slots in all (a power of two) and shards (a power of two dividing it). 2^16 slots hold
  // about 6 MB per index that answered outside-volume queries. Repeats answered, armadillo
  // n = 64 / dragon n = 128: 2^15 slots 28 189 / 81 735, 2^16 29 166 / 87 282, 2^22
  // 30 206 / 93 919 (of 136 702 / 293 657 queries).
  static constexpr uint64_t kSlots = uint64_t{1} << 16;
  static constexpr uint64_t kShards = 64;

  // The memo's answer for `ball`, if it holds one.
  bool find(const Sphere& ball, OutsideVolume* out) const {
    const Key k = keyOf(ball);
    const uint64_t h = hashOf(k);
    Shard& s = shard(h);
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.slots.empty()) return false;
    const Slot& slot = s.slots[slotOf(h)];
    if (!slot.used || slot.key != k) return false;
    *out = slot.value;
    return true;
  }

  void store(const Sphere& ball, const OutsideVolume& value) const {
    const Key k = keyOf(ball);
    const uint64_t h = hashOf(k);
    Shard& s = shard(h);
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.slots.empty()) s.slots.resize(kSlots / kShards);
    s.slots[slotOf(h)] = {k, value, true};
  }

 private:
  using Key = std::array<uint64_t, 4>;
  struct Slot {
    Key key{};
    OutsideVolume value;
    bool used = false;
  };
  struct Shard {
    std::mutex mutex;
    std::vector<Slot> slots;  // empty until the shard's first store
  };

  static Key keyOf(const Sphere& ball) {
    Key k;
    std::memcpy(&k[0], &ball.center[0], sizeof(double));
    std::memcpy(&k[1], &ball.center[1], sizeof(double));
    std::memcpy(&k[2], &ball.center[2], sizeof(double));
    std::memcpy(&k[3], &ball.radius, sizeof(double));
    return k;
  }
  // A multiply-xorshift mix of the four words (splitmix64's finaliser).
  static uint64_t hashOf(const Key& k) {
    uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (const uint64_t w : k) {
      h ^= w;
      h ^= h >> 30;
      h *= 0xbf58476d1ce4e5b9ULL;
      h ^= h >> 27;
      h *= 0x94d049bb133111ebULL;
      h ^= h >> 31;
    }
    return h;
  }
  Shard& shard(uint64_t h) const { return shards_[h & (kShards - 1)]; }
  static uint64_t slotOf(uint64_t h) { return (h >> 32) & (kSlots / kShards - 1); }

  mutable std::array<Shard, kShards> shards_;
};

}  // namespace sphereset::detail
