// Initial cluster centres. Reference: Wang et al. 2006, Sec. 5 ("Preprocessing"): "we
// randomly choose n_s inner points for the sphere centers o_i and set their radii r_i = 0".
// Deviation: by default the seeds are spread by farthest-point sampling over the inner points
// instead (Sec. 8 suggests better initial spheres for large sets); random inner points remain
// an option.
#include "fit/seeding.hpp"

#include <algorithm>
#include <limits>
#include <random>

#include "fit/fit_common.hpp"
#include "util/sampling.hpp"

namespace sphereset::detail {

std::vector<Vec3> initialCentres(const PointSet& ps, int n, FitInit init, uint64_t seed) {
  // The seeds are inner points as in the paper when there are at least n of them. Fewer
  // happen with few points in all (half of them are inner by default), a low interior share
  // or a solid too thin for its grid; then the seeds are drawn from all the points, so that
  // every sphere gets one (fitSpheres asks for at most as many spheres as there are points).
  const int64_t all = static_cast<int64_t>(ps.points.size());
  const int64_t pool = ps.interior >= n ? ps.interior : all;
  std::mt19937_64 rng(mixSeed(seed, 11));
  std::vector<Vec3> out;
  if (init == FitInit::kRandom || pool <= n) {
    std::vector<int64_t> idx(pool);
    for (int64_t i = 0; i < pool; ++i) idx[i] = i;
    std::shuffle(idx.begin(), idx.end(), rng);
    for (int64_t i = 0; i < std::min<int64_t>(n, pool); ++i) out.push_back(ps.points[idx[i]]);
    return out;
  }
  std::vector<double> d2(pool, std::numeric_limits<double>::infinity());
  int64_t next = static_cast<int64_t>(uniform01(rng) * pool) % pool;
  for (int k = 0; k < n; ++k) {
    pollCancel();
    out.push_back(ps.points[next]);
    int64_t far = 0;
    for (int64_t i = 0; i < pool; ++i) {
      d2[i] = std::min(d2[i], (ps.points[i] - out.back()).squaredNorm());
      if (d2[i] > d2[far]) far = i;
    }
    next = far;
  }
  return out;
}

}  // namespace sphereset::detail
