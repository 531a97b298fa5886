// Bindings of the fit: sphereset.fit with the options and defaults of `sphereset fit`, the
// progress callback, and cancellation by Ctrl-C.
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <variant>

#include "fit_args.hpp"
#include "solid.hpp"
#include "sphereset/animate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/tree.hpp"

namespace sphereset::python {

FitRequest fitRequest(const py::dict& options) {
  FitRequest rq;
  setOptions(options, [&](const std::string& name, const std::string& text) {
    return setFitRequestOption(&rq, name, text);
  });
  return rq;
}

FitOptions fitOptions(const py::dict& options) { return fitOptionsFor(fitRequest(options)); }

ToleranceOptions toleranceOptions(const py::dict& tolerance) {
  ToleranceOptions to;
  setOptions(tolerance, [&](const std::string& name, const std::string& text) {
    return setToleranceOption(&to, name, text);
  });
  return to;
}

py::list optionTable(std::span<const OptionSpec> table) {
  py::list rows;
  for (const OptionSpec& o : table) {
    py::dict d;
    d["name"] = o.name;
    d["flag"] = o.flag;
    d["type"] = o.type == OptionType::kChoice ? "choice"
                : o.type == OptionType::kReal ? "real"
                                              : "integer";
    d["min"] = o.min;
    d["max"] = o.max;
    d["above_min"] = o.above_min;
    d["percent"] = o.percent;
    py::list choices;
    for (const char* c : o.choices) choices.append(c);
    d["choices"] = choices;
    d["default"] = o.default_text;
    d["help"] = o.help;
    d["key"] = o.key ? py::object(py::str(o.key)) : py::object(py::none());
    d["automatic"] = o.automatic ? py::object(py::str(o.automatic)) : py::object(py::none());
    rows.append(d);
  }
  return rows;
}

void installProgress(FitOptions* fo, const py::object& progress) {
  const py::object* cb = &progress;
  fo->progress = [cb](const FitProgress& p) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (cb->is_none()) return;
    py::dict d;
    d["phase"] = p.phase;
    d["iteration"] = p.iteration;
    d["energy"] = p.energy;
    d["spheres"] = p.spheres;
    d["seconds"] = p.seconds;
    (*cb)(d);
  };
}

py::dict fieldsDict(const std::vector<ResultField>& fields) {
  py::dict d;
  for (const ResultField& f : fields) {
    py::object value = std::visit(
        [](const auto& v) -> py::object {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::vector<double>>)
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
          else if constexpr (std::is_same_v<T, std::vector<int64_t>>)
            return py::array_t<int64_t>(static_cast<py::ssize_t>(v.size()), v.data());
          else if constexpr (std::is_same_v<T, std::string>)
            return text(v);
          else
            return py::cast(v);
        },
        f.value);
    const std::string name = f.name;
    const size_t dot = name.find('.');
    if (dot == std::string::npos) {
      d[py::str(name)] = value;
      continue;
    }
    const py::str group(name.substr(0, dot));
    if (!d.contains(group)) d[group] = py::dict();
    py::dict members = d[group];
    members[py::str(name.substr(dot + 1))] = value;
  }
  return d;
}

py::dict fitResultDict(const FitResult& r, double volume) {
  py::dict d = fieldsDict(fitResultFields(r, volume));
  d["spheres"] = spheresToArray(r.spheres);
  return d;
}

// The fields of a result kind without values: name, type (bool, int, float, array) and help,
// from which scripts/update_stubs.sh writes the Python result classes.
py::list resultSchema(const std::vector<ResultField>& fields) {
  py::list rows;
  for (const ResultField& f : fields) {
    py::dict row;
    row["name"] = f.name;
    row["type"] = std::visit(
        [](const auto& v) -> const char* {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) return "bool";
          if constexpr (std::is_same_v<T, int64_t>) return "int";
          if constexpr (std::is_same_v<T, double>) return "float";
          if constexpr (std::is_same_v<T, std::string>) return "str";
          if constexpr (std::is_same_v<T, std::vector<double>>) return "array";
          if constexpr (std::is_same_v<T, std::vector<int64_t>>) return "int_array";
          return "str_list";
        },
        f.value);
    row["help"] = f.help;
    rows.append(row);
  }
  return rows;
}

py::dict optionsDict(const FitOptions& fo) {
  py::dict d;
  d["n"] = fo.num_spheres;
  d["seed"] = fo.seed;
  d["method"] = fitMethodName(fo.method);
  d["points"] = fo.target_points;
  d["interior_share"] = fo.interior_share;
  d["iterations"] = fo.max_iterations;
  d["tolerance"] = fo.tolerance;
  d["max_failed_teleports"] = fo.max_failed_teleports;
  d["init"] = fitInitName(fo.init);
  d["optimizer"] = sphereOptimizerName(fo.optimizer);
  d["optimizer_evaluations"] = fo.optimizer_evaluations;
  d["padding"] = fo.padding;
  d["shrink_passes"] = fo.shrink_passes;
  d["decimation"] = fo.decimation;
  d["restarts"] = fo.restarts;
  return d;
}

void bindFit(py::module_& m) {
  m.def(
      "_fit",
      [](const std::shared_ptr<PySolid>& solid, const py::dict& options,
         const py::object& progress) {
        FitOptions fo = fitOptions(options);
        fo.original = solid->original();
        installProgress(&fo, progress);
        Expected<FitResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = fitSpheres(*solid->index, fo);
        }
        if (!r) raise(r.error().code, solid->name + ": " + r.error().message);
        py::dict d = fitResultDict(*r, signedVolume(solid->repair.solid));
        d["options"] = optionsDict(fo);
        d["repair"] = repairDict(solid->repair);
        return d;
      },
      py::arg("solid"), py::arg("options"), py::arg("progress"));
  bindToleranceFits(m);
  m.def(
      "_check_fit_options", [](const py::dict& options) { fitRequest(options); },
      py::arg("options"));
  m.def("_fit_option_table", [] { return optionTable(fitRequestOptions()); });
  m.def(
      "_result_schema",
      [](const std::string& kind) {
        if (kind == "fit") return resultSchema(fitResultFields(FitResult{}, 1.0));
        if (kind == "eval") return resultSchema(evalResultFields(EvalResult{}));
        if (kind == "robot") return resultSchema(robotFitFields(RobotFitResult{}));
        if (kind == "robot_link") return resultSchema(robotLinkFields(RobotLinkFit{}));
        if (kind == "animate") return resultSchema(animateResultFields(AnimateResult{}));
        if (kind == "animate_frame") return resultSchema(animateFrameFields(AnimateFrameResult{}));
        if (kind == "repair") return resultSchema(repairResultFields(RepairResult{}));
        if (kind == "diagnosis") return resultSchema(meshDiagnosisFields(MeshDiagnosis{}));
        if (kind == "load") return resultSchema(loadReportFields(LoadReport{}));
        if (kind == "shells") return resultSchema(shellCountFields(ShellCounts{}));
        if (kind == "tree_level") return resultSchema(treeLevelFields(TreeLevelStats{}, 1.0));
        raise(ErrorCode::kInvalidArgument,
              "no result kind '" + kind +
                  "' (expected fit, eval, robot, robot_link, animate, animate_frame, repair, "
                  "diagnosis, load, shells or tree_level)");
      },
      py::arg("kind"));
}

}  // namespace sphereset::python
