// The objects the bindings share between topics: a mesh as the user holds it (loaded or made
// from arrays) and the solid made of it by the repair, with its index, ready to fit and measure.
#pragma once

#include <memory>
#include <string>

#include "common.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::python {

// sphereset.Mesh: the triangles and what the clean-up did (LoadReport).
struct PyMesh {
  LoadedMesh loaded;
};

// sphereset.Solid: a mesh made a solid (repair.hpp), indexed. Built once, fitted and evaluated
// many times.
struct PySolid {
  std::shared_ptr<const PyMesh> input;
  RepairResult repair;
  std::unique_ptr<SolidIndex> index;
  std::string name;
  // The input triangles when the solid differs from them (fit and evaluation cover them too),
  // else null: as the command line decides it.
  const Mesh* original() const { return originalTriangles(repair); }
  const Mesh* walls() const { return envelopeWalls(repair); }
};

// The repair's options from the Python keywords (repair "auto"/"off", weld tolerance, cavities,
// wrapping), with the union and the wrapping of this build.
RepairOptions repairOptions(const std::string& repair, double weld_tolerance, bool fill_cavities,
                            double wrap_alpha, double wrap_offset,
                            const std::string& fill_openings);

py::dict repairDict(const RepairResult& r);
py::dict diagnosisDict(const MeshDiagnosis& d);

}  // namespace sphereset::python
