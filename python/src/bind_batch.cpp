// Bindings of the batch core (batch.hpp) for distributed runners (sphereset/batch.py): items
// and options cross process boundaries as plain dicts, each worker processes one item as
// `sphereset batch` does, and the driver appends the report lines in item order.
#include "fit_args.hpp"
#include "solid.hpp"
#include "sphereset/batch.hpp"

namespace sphereset::python {
namespace {

py::dict requestDict(const FitRequest& r) {
  py::dict d;
  // n only when given, so that an item keeps "not given" across processes (a tolerance then
  // chooses its count: checkToleranceRequest).
  d["n"] = r.count_given ? py::object(py::int_(r.num_spheres)) : py::object(py::none());
  d["quality"] = fitQualityName(r.quality);
  d["seed"] = r.seed;
  d["padding"] = r.padding;
  d["points"] = r.points;
  d["iterations"] = r.iterations ? py::object(py::int_(*r.iterations)) : py::object(py::none());
  d["restarts"] = r.restarts ? py::object(py::int_(*r.restarts)) : py::object(py::none());
  d["decimation"] = r.decimation ? py::object(py::float_(*r.decimation)) : py::object(py::none());
  d["optimizer"] = sphereOptimizerName(r.optimizer);
  d["init"] = fitInitName(r.init);
  d["method"] = fitMethodName(r.method);
  return d;
}

// The library's fit table parses the dict's values (fit_args.hpp), with its messages.
FitRequest requestFrom(const py::dict& d) { return fitRequest(d); }

// A tolerance as the texts its table parses ({max_protrusion: "0.01" or "5%", max_er,
// max_spheres}; None for a limit not set), and back (setToleranceOption, its messages).
py::dict toleranceDict(const ToleranceOptions& t) {
  py::dict d;
  d["max_protrusion"] =
      t.max_protrusion_fraction > 0.0
          ? py::object(py::str(optionText(100.0 * t.max_protrusion_fraction) + "%"))
      : t.max_protrusion > 0.0 ? py::object(py::str(optionText(t.max_protrusion)))
                               : py::object(py::none());
  d["max_er"] = t.max_er > 0.0 ? py::object(py::str(optionText(t.max_er))) : py::object(py::none());
  // The cap when set (a batch's cap that a line with a limit takes).
  d["max_spheres"] =
      t.capSet() ? py::object(py::str(std::to_string(t.max_spheres))) : py::object(py::none());
  return d;
}
ToleranceOptions toleranceFrom(const py::object& o) {
  return o.is_none() ? ToleranceOptions{} : toleranceOptions(o.cast<py::dict>());
}

py::dict itemDict(const BatchItem& i) {
  py::dict d;
  d["mesh"] = i.mesh;
  d["output"] = i.output;
  d["origin"] = i.origin;
  d["fit"] = requestDict(i.fit);
  d["tolerance"] = toleranceDict(i.tolerance);
  return d;
}

BatchItem itemFrom(const py::dict& d) {
  BatchItem i;
  i.mesh = d["mesh"].cast<std::string>();
  i.output = d["output"].cast<std::string>();
  i.origin = d["origin"].cast<std::string>();
  i.fit = requestFrom(d["fit"].cast<py::dict>());
  if (d.contains("tolerance")) i.tolerance = toleranceFrom(d["tolerance"]);
  return i;
}

// Options dict: {"fit": request, "tolerance": {max_protrusion, max_er, max_spheres} (optional),
// "repair": "auto"/"off", "weld_tolerance", "fill_cavities", "wrap_alpha", "wrap_offset",
// "fill_openings" (text), "format", "resume", "threads", "best_effort" (optional)}.
BatchOptions optionsFrom(const py::dict& d) {
  BatchOptions o;
  o.fit = requestFrom(d["fit"].cast<py::dict>());
  if (d.contains("tolerance")) o.tolerance = toleranceFrom(d["tolerance"]);
  o.repair = repairOptions(d["repair"].cast<std::string>(), d["weld_tolerance"].cast<double>(),
                           d["fill_cavities"].cast<bool>(), d["wrap_alpha"].cast<double>(),
                           d["wrap_offset"].cast<double>(), d["fill_openings"].cast<std::string>());
  o.format = d["format"].cast<std::string>();
  o.resume = d["resume"].cast<bool>();
  o.threads = d["threads"].cast<int>();
  if (d.contains("best_effort")) o.best_effort = d["best_effort"].cast<bool>();
  return o;
}

}  // namespace

void bindBatch(py::module_& m) {
  m.def(
      "_batch_items",
      [](const Path& input_arg, const py::dict& options) {
        const std::string input = input_arg.string();
        const BatchOptions o = optionsFrom(options);
        std::vector<BatchItem> items;
        {
          py::gil_scoped_release release;
          items = unwrap(listBatchItems(input, o));
        }
        py::list out;
        for (const BatchItem& i : items) out.append(itemDict(i));
        return out;
      },
      py::arg("input"), py::arg("options"),
      "The items of a batch (listBatchItems), as dicts {mesh, output, origin, fit, tolerance}.");
  m.def(
      "_batch_process",
      [](const py::dict& item, const Path& out_dir_arg, const py::dict& options) {
        const std::string out_dir = out_dir_arg.string();
        const BatchItem i = itemFrom(item);
        const BatchOptions o = optionsFrom(options);
        py::gil_scoped_release release;
        const BatchItemReport r = processBatchItem(i, out_dir, o);
        return reportLine(r);
      },
      py::arg("item"), py::arg("out_dir"), py::arg("options"),
      "Processes one item as `sphereset batch` does (skipped when up to date and resuming) and "
      "returns its report line.");
  m.def(
      "_batch_done",
      [](const py::dict& item, const Path& out_dir_arg, const py::dict& options) {
        const std::string out_dir = out_dir_arg.string();
        const BatchItem i = itemFrom(item);
        const BatchOptions o = optionsFrom(options);
        py::gil_scoped_release release;
        return batchItemDone(i, out_dir, o);
      },
      py::arg("item"), py::arg("out_dir"), py::arg("options"));
  m.def(
      "_check_output_folder",
      [](const Path& folder, const std::vector<std::string>& inputs) {
        check(checkOutputFolder(folder.string(), inputs));
      },
      py::arg("folder"), py::arg("inputs"));
  py::class_<BatchReport>(m, "_BatchReport",
                          "One run's report and its lock on the output folder (batch.hpp).")
      .def(py::init(
               [](const Path& out_dir) { return unwrap(BatchReport::start(out_dir.string())); }),
           py::arg("out_dir"))
      .def(
          "append",
          [](BatchReport& r, const std::string& line) {
            check(r.append(unwrap(parseReportLine(line))));
          },
          py::arg("line"), "Appends a report line (as _batch_process returns it).")
      .def(
          "finish", [](BatchReport& r) { check(r.finish()); },
          "Replaces OUT/report.jsonl with this run's report and releases the folder.");
  m.def("_batch_report_path", &batchReportPath, py::arg("out_dir"));
  m.def(
      "_batch_end",
      [](const std::vector<std::string>& lines, const std::string& input, const Path& out_dir) {
        BatchTotals totals;
        for (const std::string& line : lines)
          countBatchItem(unwrap(parseReportLine(line)), &totals);
        const BatchEnd end = batchEnd(totals, input, out_dir.string());
        py::dict d;
        d["summary"] = end.summary;
        d["exit_code"] = end.exit_code;
        d["message"] = end.message;
        return d;
      },
      py::arg("lines"), py::arg("input"), py::arg("out_dir"),
      "How a run of these report lines ends (batch.hpp: batchEnd): summary, exit_code, message.");
}

}  // namespace sphereset::python
