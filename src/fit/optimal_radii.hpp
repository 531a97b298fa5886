// Private: optimal radii for given centres, a covering integer program (optimal_radii.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset::detail {

struct RadiiStats {
  bool solved = false;       // an integer solution was found
  bool kept = false;         // the bounded solution lowered the outside volume and replaced *sp
  bool proven = false;       // the program was solved to proven optimality
  double objective = 0.0;    // Σ outside volume of the program's solution (absolute)
  double lower_bound = 0.0;  // the program's proven lower bound (branch and bound)
  int64_t units = 0;         // surface pieces and interior points of the program
  int64_t rows = 0;          // its coverage rows after reduction
  int64_t columns = 0;       // its radius levels, over all spheres
  int64_t queries = 0;       // outside-volume evaluations
  double start = 0.0;        // Σ outside volume of *sp at the start
  double energy = 0.0;       // Σ outside volume of *sp at the end
};

// Chooses the radii of the spheres `sp` (a set covering the surface of the index's mesh), their
// centres fixed, so that every unit (the surface split until one sphere holds each piece, down to
// `unit_edge`, and the points `interior`) lies in a sphere at least total outside volume; the
// solution is bounded exactly (pieces down to `bound_edge`) and replaces *sp only if that lowers
// the total outside volume. Deterministic whatever the number of threads.
RadiiStats optimalRadii(const SolidIndex& index, const std::vector<Vec3>& interior,
                        double unit_edge, double bound_edge, std::vector<Sphere>* sp);

// optimalRadii as the fit runs it (units and bound at kRefineFineEdge * min_edge), its figures
// written to res->radii, its queries and seconds added.
void runOptimalRadii(const SolidIndex& index, const std::vector<Vec3>& interior, double min_edge,
                     std::vector<Sphere>* sp, FitResult* res);

}  // namespace sphereset::detail
