// The coverage rules shared by the fit's guaranteed bound and the evaluation's certificates:
// how deep surface pieces and interior cells are split, and the rounding a certificate forgives.
#pragma once

namespace sphereset {

// Triangles are split in four at most this many times, by the fit's guaranteed bound and by
// the evaluation's surface certificate alike: a set the bound made to cover is certified.
inline constexpr int kSurfaceSplitDepth = 10;

// Octree levels below an 8³ grid of the bounds that the interior certificate refines to, by
// default (EvalOptions::interior_max_depth), and that the fit's interior bound uses.
inline constexpr int kInteriorSplitDepth = 5;

// The coverage certificates accept points within this fraction of the bounding-box diagonal
// outside a sphere, so that a set built to touch the surface exactly (a circumscribed sphere)
// is not refuted by the last bit of rounding. (The fit's bound needs none of it: it grows radii
// by a slack of the same size beyond what each piece needs.)
inline constexpr double kCoverageToleranceRel = 1e-12;

}  // namespace sphereset
