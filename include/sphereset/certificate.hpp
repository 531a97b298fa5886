// The coverage certificate of a sphere set, kept up to date as single spheres change (the
// interactive view edits one sphere at a time). After an edit only the triangles and interior
// cells near the old or the new ball are certified again; the result is always the one
// evaluateSpheres gives for the same set and depths (its certificate fields and E_r summed).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "sphereset/cover.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

struct CertificateOptions {
  // The triangles of the input a repaired solid was made from (repair.hpp), certified as
  // covered too, as EvalOptions::original; copied, may be null.
  const Mesh* original = nullptr;
  int surface_max_depth = kSurfaceSplitDepth;    // as EvalOptions::surface_max_depth
  int interior_max_depth = kInteriorSplitDepth;  // as EvalOptions::interior_max_depth
  // Called from the calling thread every `poll_interval` seconds or so inside the long loops;
  // it may throw to cancel (as EvalOptions::poll). A cancelled call leaves the set as it was
  // before the call, and the next call certifies it in full.
  std::function<void()> poll;
  double poll_interval = 0.25;
};

// The certificate of the current set: the fields of EvalResult of the same names, equal to
// them, plus the triangles not certified and what the last update cost.
struct CertificateSummary {
  int64_t spheres = 0;
  double volume = 0.0;                 // the solid's (EvalResult::mesh_volume)
  double bbox_diagonal = 0.0;          // gaps below are relative to it
  double er_sum = 0.0;                 // Σ_i SOV(S_i) / volume, exact
  std::vector<double> outside_volume;  // per sphere, exact
  bool surface_covered = false;
  bool original_covered = true;  // true when there is no original
  bool interior_covered = false;
  bool covered = false;          // all three
  double max_surface_gap = 0.0;  // / diag
  double max_original_gap = 0.0;
  double max_interior_gap = 0.0;
  double max_gap = 0.0;  // the largest of the three
  double surface_uncertified_area = 0.0;
  int64_t interior_uncertified_cells = 0;
  // Triangles not certified, in increasing order: of the solid, and of the original.
  std::vector<int64_t> uncovered_triangles;
  std::vector<int64_t> original_uncovered_triangles;
  // The last update (the full certificate when the object was made or after setSpheres): its
  // wall-clock time, and the triangles and octree cells it certified again, out of how many.
  double seconds = 0.0;
  int64_t triangles_rechecked = 0;
  int64_t original_triangles_rechecked = 0;
  int64_t cells_rechecked = 0;
  int64_t triangles = 0;
  int64_t original_triangles = 0;
  int64_t cells = 0;  // cells of the octree walk as it stands
};

// One set's certificate under edits. Not for use from several threads at once (each call runs
// its loops in parallel itself).
class CoverageCertificate {
 public:
  CoverageCertificate(CoverageCertificate&&) noexcept;
  CoverageCertificate& operator=(CoverageCertificate&&) noexcept;
  ~CoverageCertificate();

  // Each edit checks its input first and changes nothing when it returns an error
  // (kInvalidArgument): an index out of range, a sphere with a NaN, infinite or negative value,
  // a set that would be empty or hold more than limits::kMaxSpheres spheres. Indices refer to
  // the set as the edit finds it; removing a sphere shifts the ones after it down by one.
  Status setSphere(int index, const Sphere& sphere);
  Status addSphere(const Sphere& sphere);
  Status removeSphere(int index);
  Status setSpheres(std::vector<Sphere> spheres);  // a new set: certified in full
  // A new set certified once against the current one: the spheres that differ at the same
  // index, those added at the end and those the new set no longer has at the end count as
  // changed, as if each were edited in turn (the summary's coverage figures and E_r are the
  // same; its rechecked counts and seconds are the batch's); in full (setSpheres) when more than
  // kFullUpdateShare of the larger set's spheres changed, or nothing is certified yet (also after
  // a cancelled call).
  Status updateSpheres(std::vector<Sphere> spheres);
  static constexpr double kFullUpdateShare = 0.5;

  const std::vector<Sphere>& spheres() const;
  const CertificateSummary& summary() const;

  struct State;  // opaque; defined in the library's sources

 private:
  friend Expected<CoverageCertificate> makeCoverageCertificate(const SolidIndex&,
                                                               std::vector<Sphere>,
                                                               const CertificateOptions&);
  explicit CoverageCertificate(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// Certifies the set in full. The solid must be closed (callers check with diagnoseMesh first)
// and must outlive the certificate. Errors (kInvalidArgument): depths or poll interval outside
// the evaluation's limits (evalOptionTable), or spheres refused as by the edits.
Expected<CoverageCertificate> makeCoverageCertificate(const SolidIndex& solid,
                                                      std::vector<Sphere> spheres,
                                                      const CertificateOptions& options = {});

}  // namespace sphereset
