// The link envelope: what a motion planner treats as a link, its walls together with the hollow
// they enclose and the openings up to a size. A robot's casings (a shoulder shell, a forearm
// tube) are thin walls open at their ends; fitted as walls, a sphere set spends its spheres
// avoiding a hollow that nothing can reach without passing a joint, and E_r against the wall
// volume is 3 to 5.
//
// Method: a second wrap from outside, CGAL's 3D Alpha Wrapping (Portaneri, Rouxel-Labbé, Hemmer,
// Cohen-Steiner, Alliez 2022, "Alpha Wrapping with an Offset"), of the walls' surface with a
// carving ball of diameter `size` (alpha = size / 2). The ball comes from outside and enters no
// opening narrower than itself, so such openings are closed and whatever lies behind them, the
// hollow, is inside; a wide opening stays open. The alternatives (docs/algorithm.md): capping
// the openings' boundary loops needs them to be loops, while a casing's rims are closed walls;
// a closing on a voxel grid needs an exact surface made afterwards. The wrap gives that surface
// directly (closed, 2-manifold, free of crossings, strictly containing every input triangle),
// so the envelope contains the walls and the original triangles, and its cost falls with the
// ball's size. Its offset is the walls' own automatic wrap offset (or RepairOptions::wrap_offset),
// a thin layer, not the ball.
#include "repair/envelope.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "repair/canonical_order.hpp"
#include "repair/wrap_parameters.hpp"

namespace sphereset::detail {
namespace {

// The automatic size: the walls' bounding box's smallest extent (a tube's or casing's width:
// its ends are closed; a tray wide open on top keeps its opening), at least this fraction of
// the diagonal (a thin plate's thickness would ask for a very fine wrap and closes nothing).
constexpr double kEnvelopeMinSizeRel = 1.0 / 20.0;
// With the automatic size, the envelope is kept only when it encloses a hollow: its volume at
// least this many times the walls'. A casing's or a tube's envelope is 2 to 2.6 times its
// walls (the Kinova Gen3's shoulder, half arm and forearm; a tube whose wall is a fifth of its
// radius: 2.8), while one that only rounds the walls' concavities adds 5 to 35 % (its base,
// wrists and second half arm), which a planner gains nothing from and the spheres would have to
// cover; then the walls are the solid. A size the user gives is always applied.
constexpr double kHollowVolumeRatio = 1.5;

}  // namespace

Status closeOpenings(const RepairOptions& o, const std::string& name, RepairResult* res) {
  if (!o.operations.wrap)
    return Error{ErrorCode::kNotSolid, name +
                                           ": fill_openings needs the wrapping; rebuild with "
                                           "SPHERESET_WITH_REPAIR=ON"};
  const Mesh& walls = res->solid;
  const Aabb box = boundingBox(walls);
  const double diag = box.diagonal();
  const bool automatic = o.fill_openings == kAutomatic;
  double size = o.fill_openings;
  if (automatic) size = std::max((box.max - box.min).minCoeff(), kEnvelopeMinSizeRel * diag);
  // A ball wider than the whole shape closes everything a ball of the diagonal's width closes.
  const double alpha = std::min(size, diag) / 2.0;
  RepairOptions automatic_wrap;
  automatic_wrap.wrap_offset = o.wrap_offset;
  double unused_alpha = 0.0, offset = 0.0;
  wrapParameters(walls, automatic_wrap, &unused_alpha, &offset);
  if (Status st = checkWrap(walls, false, alpha, offset, name); !st) return st;
  const double predicted = predictedWrapTriangles(walls, alpha, offset);
  if (!(predicted <= kMaxWrapTriangles))
    return Error{ErrorCode::kInvalidArgument,
                 name + ": fill_openings " + numberFormat("%.3g", size) +
                     " is too small for this mesh: its envelope would have about " +
                     numberFormat("%.3g", predicted) + " triangles (the limit is " +
                     numberFormat("%.3g", kMaxWrapTriangles) + "); give a larger size"};
  auto w = o.operations.wrap(walls, alpha, offset);
  if (!w) return Error{w.error().code, name + ": " + w.error().message};
  const double walls_volume = signedVolume(walls);
  const double ratio = signedVolume(*w) / walls_volume;
  if (automatic && !o.keep_envelope && ratio < kHollowVolumeRatio) {
    res->notes.push_back("no hollow behind openings narrower than " + numberFormat("%.3g", size) +
                         " (the bounding box's smallest extent): their envelope would be " +
                         numberFormat("%.3g", ratio) + " times the walls' volume, below " +
                         numberFormat("%.3g", kHollowVolumeRatio) + "; the walls are the solid");
    return {};
  }
  res->walls = std::move(res->solid);
  res->solid = canonicalOrder(std::move(w).value());
  res->fill_openings = size;
  res->notes.push_back("openings narrower than " + numberFormat("%.3g", size) +
                       (automatic ? " (the bounding box's smallest extent)" : "") +
                       " closed: the envelope's volume is " + numberFormat("%.3g", ratio) +
                       " times the walls'");
  return {};
}

}  // namespace sphereset::detail
