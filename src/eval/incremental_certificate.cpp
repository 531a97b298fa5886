// The incremental coverage certificate (certificate.hpp): E_r summed and the surface, original
// and interior certificates of evaluateSpheres, kept up to date as one sphere at a time changes
// (or several at once: updateSpheres, where the argument below holds for each changed ball).
//
// Why it equals the full certificate: both judge every triangle with certifyTriangle and every
// interior cube with cellVerdict (eval/coverage_pieces.hpp, cover/cover_cells.hpp) and sum with
// the same functions in the same order; this file only decides which verdicts to compute again.
// A triangle's verdict depends on the spheres through the tests "does one sphere hold these
// three points" and "is this point in the union", and through its gap: the largest, over the
// points it tested outside the union, of the distance to the nearest sphere. When a sphere
// changes from ball B to ball B' (B alone for a removal, B' alone for an addition), a triangle
// whose stored gap is G and that neither B nor B' comes within G of (up to a rounding margin)
// sees none of its tests change: neither ball holds any of its points, and at each point p it
// tested outside the union, gap(p) <= G < d(p, B), d(p, B'), so the nearest sphere is another
// one, before and after. Its stored verdict is then the one a full evaluation would compute; the
// other triangles are judged again. The interior's octree works the same way cube by cube
// (eval/cell_forest.cpp). The widening by G is what makes gaps exact: a far triangle whose
// nearest sphere was B must be judged again when B moves, though B never touched it.
// The outside volume of one sphere depends on that sphere alone.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <string>

#include "eval/cell_forest.hpp"
#include "eval/coverage_pieces.hpp"
#include "sphereset/certificate.hpp"
#include "sphereset/evaluate.hpp"
#include "util/poll.hpp"

namespace sphereset {
namespace {

// One mesh's surface certificate, triangle by triangle, with each triangle's bounding box.
struct TriangleCovers {
  const Mesh* mesh = nullptr;
  std::vector<Aabb> boxes;
  std::vector<detail::PieceCover> pieces;

  void reset(const Mesh* m) {
    mesh = m;
    boxes.assign(m->triangles.size(), Aabb{});
    for (size_t t = 0; t < boxes.size(); ++t)
      for (int k = 0; k < 3; ++k) boxes[t].extend(m->vertices[m->triangles[t][k]]);
    pieces.assign(m->triangles.size(), {});
  }

  // Judges again every triangle (changed empty and all true) or those one of the changed balls
  // comes within the triangle's stored gap of. Returns how many were judged.
  int64_t certify(const detail::SphereGrid& grown, int max_depth, std::span<const Sphere> changed,
                  bool all) {
    std::atomic<int64_t> judged{0};
    tbb::parallel_for(size_t{0}, pieces.size(), [&](size_t t) {
      bool near = all;
      for (const Sphere& b : changed)
        near = near || detail::ballNearBox(b, boxes[t].min, boxes[t].max, pieces[t].gap);
      if (!near) return;
      detail::pollCancel();
      pieces[t] = detail::certifyTriangle(grown, *mesh, t, max_depth);
      judged.fetch_add(1, std::memory_order_relaxed);
    });
    return judged.load();
  }
};

Status checkIndex(int index, size_t count) {
  if (index < 0 || static_cast<size_t>(index) >= count)
    return Error{ErrorCode::kInvalidArgument, "sphere index " + std::to_string(index) +
                                                  " is out of range (the set has " +
                                                  std::to_string(count) + " spheres)"};
  return {};
}

}  // namespace

struct CoverageCertificate::State {
  const SolidIndex* solid = nullptr;
  std::optional<Mesh> original;
  int surface_depth = kSurfaceSplitDepth;
  std::function<void()> poll;
  double poll_interval = detail::kPollSeconds;
  double volume = 0.0, diag = 0.0;

  std::vector<Sphere> spheres, grown;
  detail::SphereGrid grid{grown};
  std::vector<double> outside;  // per sphere, exact
  TriangleCovers surface, original_surface;
  detail::CellForest forest;
  bool needs_full = true;  // nothing certified yet, or a call was cancelled midway
  CertificateSummary summary;

  State(const SolidIndex& s, const CertificateOptions& o)
      : solid(&s),
        surface_depth(o.surface_max_depth),
        poll(o.poll),
        poll_interval(o.poll_interval),
        forest(s, o.interior_max_depth) {
    if (o.original) original = *o.original;
    volume = signedVolume(s.mesh());
    diag = s.bounds().diagonal();
    surface.reset(&s.mesh());
    if (original) original_surface.reset(&*original);
  }

  double diagonal() const { return diag > 0.0 ? diag : 1.0; }

  // Certifies the current set: in full, or after the balls `changed` (grown) changed.
  void certify(std::span<const Sphere> changed, std::optional<size_t> changed_sphere);
  void summarize(double seconds, int64_t triangles, int64_t original_triangles, int64_t cells);
};

void CoverageCertificate::State::certify(std::span<const Sphere> changed,
                                         std::optional<size_t> changed_sphere) {
  const auto t0 = std::chrono::steady_clock::now();
  const detail::PollScope scope(poll, poll_interval);
  grid = detail::SphereGrid(grown);
  const bool full = needs_full;
  needs_full = true;  // until this call completes
  if (full) {
    outside.assign(spheres.size(), 0.0);
    tbb::parallel_for(size_t{0}, spheres.size(), [&](size_t i) {
      detail::pollCancel();
      outside[i] = solid->outsideVolume(spheres[i]).volume;
    });
  } else if (changed_sphere) {
    outside[*changed_sphere] = solid->outsideVolume(spheres[*changed_sphere]).volume;
  }
  const int64_t tri = surface.certify(grid, surface_depth, changed, full);
  const int64_t orig = original ? original_surface.certify(grid, surface_depth, changed, full) : 0;
  const int64_t cells = full ? forest.certifyAll(grid) : forest.update(grid, changed);
  needs_full = false;
  summarize(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), tri, orig,
            cells);
}

void CoverageCertificate::State::summarize(double seconds, int64_t triangles,
                                           int64_t original_triangles, int64_t cells) {
  CertificateSummary r;
  const size_t n = spheres.size();
  const double d = diagonal();
  r.spheres = static_cast<int64_t>(n);
  r.volume = volume;
  r.bbox_diagonal = diag;
  // Summed in index order and divided as evaluateSpheres does, for the same rounding.
  double total = 0.0;
  for (double v : outside) total += v;
  r.er_sum = total / (volume > 0.0 ? volume : 1.0);
  r.outside_volume = outside;
  const detail::SurfaceCover sc =
      detail::summarizeSurface(surface.pieces, n, d, &r.uncovered_triangles);
  r.surface_covered = sc.covered;
  r.max_surface_gap = sc.max_gap;
  r.surface_uncertified_area = sc.uncertified;
  if (original) {
    const detail::SurfaceCover oc =
        detail::summarizeSurface(original_surface.pieces, n, d, &r.original_uncovered_triangles);
    r.original_covered = oc.covered;
    r.max_original_gap = oc.max_gap;
  }
  const detail::InteriorCover ic = detail::summarizeInterior(forest.roots(), n, d, sc.covered);
  r.interior_covered = ic.covered;
  r.max_interior_gap = ic.max_gap;
  r.interior_uncertified_cells = ic.uncertified_cells;
  r.covered = r.surface_covered && r.original_covered && r.interior_covered;
  r.max_gap = std::max({r.max_surface_gap, r.max_original_gap, r.max_interior_gap});
  r.seconds = seconds;
  r.triangles_rechecked = triangles;
  r.original_triangles_rechecked = original_triangles;
  r.cells_rechecked = cells;
  r.triangles = static_cast<int64_t>(surface.pieces.size());
  r.original_triangles = static_cast<int64_t>(original_surface.pieces.size());
  r.cells = forest.cellCount();
  summary = std::move(r);
}

namespace {

// Undoes an edit of the set when the certification after it does not complete (a poll threw):
// the set is as before the call, and the next call certifies in full.
template <class Undo>
class EditGuard {
 public:
  EditGuard(CoverageCertificate::State* state, Undo undo) : state_(state), undo_(undo) {}
  ~EditGuard() {
    if (!done_) {
      undo_();
      state_->needs_full = true;
      // One entry per sphere again (a cancelled full pass may have sized it for the new set);
      // the next update recomputes every entry.
      state_->outside.resize(state_->spheres.size(), 0.0);
    }
  }
  EditGuard(const EditGuard&) = delete;
  EditGuard& operator=(const EditGuard&) = delete;
  void done() { done_ = true; }

 private:
  CoverageCertificate::State* state_;
  Undo undo_;
  bool done_ = false;
};

}  // namespace

CoverageCertificate::CoverageCertificate(std::unique_ptr<State> state) : state_(std::move(state)) {}
CoverageCertificate::CoverageCertificate(CoverageCertificate&&) noexcept = default;
CoverageCertificate& CoverageCertificate::operator=(CoverageCertificate&&) noexcept = default;
CoverageCertificate::~CoverageCertificate() = default;

const std::vector<Sphere>& CoverageCertificate::spheres() const { return state_->spheres; }
const CertificateSummary& CoverageCertificate::summary() const { return state_->summary; }

Status CoverageCertificate::setSphere(int index, const Sphere& sphere) {
  State& s = *state_;
  if (Status st = checkIndex(index, s.spheres.size()); !st) return st;
  if (Status st = detail::checkSphere(sphere, index); !st) return st;
  const size_t i = static_cast<size_t>(index);
  const Sphere before = s.spheres[i];
  const double before_outside = s.outside[i];
  const Sphere changed[2] = {s.grown[i], detail::grownSphere(sphere, s.diagonal())};
  EditGuard guard(&s, [&] {
    s.spheres[i] = before;
    s.grown[i] = changed[0];
    s.outside[i] = before_outside;
  });
  s.spheres[i] = sphere;
  s.grown[i] = changed[1];
  s.certify(changed, i);
  guard.done();
  return {};
}

Status CoverageCertificate::addSphere(const Sphere& sphere) {
  State& s = *state_;
  if (Status st = detail::checkSphereCount(s.spheres.size() + 1); !st) return st;
  if (Status st = detail::checkSphere(sphere, s.spheres.size()); !st) return st;
  const Sphere added = detail::grownSphere(sphere, s.diagonal());
  EditGuard guard(&s, [&] {
    s.spheres.pop_back();
    s.grown.pop_back();
    s.outside.resize(s.spheres.size());
  });
  s.spheres.push_back(sphere);
  s.grown.push_back(added);
  s.outside.push_back(0.0);
  s.certify({&added, 1}, s.spheres.size() - 1);
  guard.done();
  return {};
}

Status CoverageCertificate::removeSphere(int index) {
  State& s = *state_;
  if (Status st = checkIndex(index, s.spheres.size()); !st) return st;
  if (Status st = detail::checkSphereCount(s.spheres.size() - 1); !st)
    return Error{st.error().code,
                 "cannot remove sphere " + std::to_string(index) + ": " + st.error().message};
  const size_t i = static_cast<size_t>(index);
  const Sphere before = s.spheres[i], removed = s.grown[i];
  const double before_outside = s.outside[i];
  EditGuard guard(&s, [&] {
    s.spheres.insert(s.spheres.begin() + index, before);
    s.grown.insert(s.grown.begin() + index, removed);
    s.outside.insert(s.outside.begin() + index, before_outside);
  });
  s.spheres.erase(s.spheres.begin() + index);
  s.grown.erase(s.grown.begin() + index);
  s.outside.erase(s.outside.begin() + index);
  s.certify({&removed, 1}, std::nullopt);
  guard.done();
  return {};
}

Status CoverageCertificate::setSpheres(std::vector<Sphere> spheres) {
  State& s = *state_;
  if (Status st = detail::checkSpheres(spheres); !st) return st;
  std::vector<Sphere> grown = detail::grownSpheres(spheres, s.diagonal());
  s.spheres.swap(spheres);
  s.grown.swap(grown);
  EditGuard guard(&s, [&] {
    s.spheres.swap(spheres);
    s.grown.swap(grown);
  });
  s.needs_full = true;
  s.certify({}, std::nullopt);
  guard.done();
  return {};
}

Status CoverageCertificate::updateSpheres(std::vector<Sphere> spheres) {
  State& s = *state_;
  if (Status st = detail::checkSpheres(spheres); !st) return st;
  const size_t n_old = s.spheres.size(), n = spheres.size();
  std::vector<size_t> differ;  // new or changed at the same index
  for (size_t i = 0; i < n; ++i)
    if (i >= n_old || spheres[i].center != s.spheres[i].center ||
        spheres[i].radius != s.spheres[i].radius)
      differ.push_back(i);
  const size_t dropped = n_old > n ? n_old - n : 0;
  if (s.needs_full ||
      static_cast<double>(differ.size() + dropped) > kFullUpdateShare * std::max(n, n_old))
    return setSpheres(std::move(spheres));
  std::vector<Sphere> grown = detail::grownSpheres(spheres, s.diagonal());
  // Each changed sphere's old and new ball (grown), as for setSphere, addSphere and removeSphere.
  std::vector<Sphere> changed;
  for (size_t i : differ) {
    if (i < n_old) changed.push_back(s.grown[i]);
    changed.push_back(grown[i]);
  }
  for (size_t i = n; i < n_old; ++i) changed.push_back(s.grown[i]);
  std::vector<double> outside = s.outside;
  outside.resize(n, 0.0);
  s.spheres.swap(spheres);
  s.grown.swap(grown);
  s.outside.swap(outside);
  EditGuard guard(&s, [&] {
    s.spheres.swap(spheres);
    s.grown.swap(grown);
    s.outside.swap(outside);
  });
  {
    const detail::PollScope scope(s.poll, s.poll_interval);
    tbb::parallel_for(size_t{0}, differ.size(), [&](size_t k) {
      detail::pollCancel();
      s.outside[differ[k]] = s.solid->outsideVolume(s.spheres[differ[k]]).volume;
    });
  }
  s.certify(changed, std::nullopt);
  guard.done();
  return {};
}

Expected<CoverageCertificate> makeCoverageCertificate(const SolidIndex& solid,
                                                      std::vector<Sphere> spheres,
                                                      const CertificateOptions& options) {
  // The depths and the poll interval within the evaluation's limits, with its messages.
  EvalOptions eval;
  eval.surface_max_depth = options.surface_max_depth;
  eval.interior_max_depth = options.interior_max_depth;
  eval.poll_interval = options.poll_interval;
  if (Status st = checkEvalOptions(eval); !st) return st.error();
  if (Status st = detail::checkSpheres(spheres); !st) return st.error();
  auto state = std::make_unique<CoverageCertificate::State>(solid, options);
  state->grown = detail::grownSpheres(spheres, state->diagonal());
  state->spheres = std::move(spheres);
  state->certify({}, std::nullopt);
  return CoverageCertificate(std::move(state));
}

}  // namespace sphereset
