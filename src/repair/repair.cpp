// Placeholder, replaced by the repair ladder.
#include "sphereset/repair.hpp"
namespace sphereset {
const char* repairName(RepairKind k) {
  switch (k) {
    case RepairKind::kNone: return "none";
    case RepairKind::kWelded: return "welded";
    case RepairKind::kCapped: return "capped";
    case RepairKind::kUnion: return "union";
    case RepairKind::kWrapped: return "wrapped";
  }
  return "none";
}
}  // namespace sphereset
