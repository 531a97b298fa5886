// Batch (batch.hpp): listing folders and manifests, bad manifest lines, one item fitted as
// fitSpheres fits it, failed items, and resuming (the report: test_batch_report.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sphereset/batch.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;
using test::TempDirTest;

// The mesh as an OFF file.
std::string offText(const Mesh& m) {
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << m.vertices.size() << ' ' << m.triangles.size() << " 0\n";
  for (const Vec3& v : m.vertices) s << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const Triangle& t : m.triangles) s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return s.str();
}

// A small, quick batch: few spheres, the fast preset.
BatchOptions quickOptions() {
  BatchOptions o;
  o.fit.num_spheres = 3;
  o.fit.quality = FitQuality::kFast;
  return o;
}

class BatchTest : public TempDirTest {
 protected:
  // Writes a file, creating its folders.
  std::string put(const std::string& name, const std::string& contents) {
    fs::create_directories(fs::path(path(name)).parent_path());
    return write(name, contents);
  }
  std::string box(const std::string& name, double size = 1.0) {
    return put(name, offText(test::makeBox(Vec3::Zero(), Vec3(size, 0.5 * size, 0.3 * size))));
  }
  std::vector<std::string> outputs(const std::vector<BatchItem>& items) {
    std::vector<std::string> o;
    for (const BatchItem& it : items) o.push_back(it.output);
    return o;
  }
};

TEST_F(BatchTest, FolderIsScannedRecursivelyInSortedOrder) {
  box("in/zeta/b.obj");
  box("in/a.stl");
  box("in/a.obj");  // shares a.json with a.stl: both keep their extension
  box("in/m/UPPER.OFF");
  box("in/.hidden/skipped.obj");
  box("in/m/.skipped.obj");
  put("in/notes.txt", "not a mesh\n");
  put("in/m/spheres.json", "{}");
  auto items = listBatchItems(path("in"), quickOptions());
  ASSERT_TRUE(items.ok()) << items.error().message;
  EXPECT_EQ(outputs(*items),
            (std::vector<std::string>{"a.obj.json", "a.stl.json", "m/UPPER.json", "zeta/b.json"}));
  EXPECT_EQ((*items)[3].mesh, (fs::path(path("in")) / "zeta/b.obj").string());
  for (const BatchItem& it : *items) {
    EXPECT_EQ(it.fit.num_spheres, 3);
    EXPECT_EQ(it.fit.quality, FitQuality::kFast);
  }
}

TEST_F(BatchTest, FolderOutputsFollowTheFormat) {
  box("in/x/c.ply");
  BatchOptions o = quickOptions();
  o.format = "yaml";
  auto items = listBatchItems(path("in"), o);
  ASSERT_TRUE(items.ok()) << items.error().message;
  EXPECT_EQ(outputs(*items), std::vector<std::string>{"x/c.yaml"});
  o.format = "obj";
  test::expectError(listBatchItems(path("in"), o), ErrorCode::kInvalidArgument, "obj", "format");
}

TEST_F(BatchTest, EmptyFolderGivesNoItems) {
  fs::create_directories(path("empty"));
  auto items = listBatchItems(path("empty"), quickOptions());
  ASSERT_TRUE(items.ok());
  EXPECT_TRUE(items->empty());
}

TEST_F(BatchTest, InputThatIsNeitherFolderNorManifestIsRefused) {
  test::expectError(listBatchItems(path("missing"), quickOptions()), ErrorCode::kUnreadable,
                    "missing", "no such file");
  const std::string mesh = box("one.obj");
  test::expectError(listBatchItems(mesh, quickOptions()), ErrorCode::kUnreadable, "one.obj",
                    "manifest");
}

TEST_F(BatchTest, CsvManifestWithPerItemOptions) {
  const std::string csv = put("lists/items.csv",
                              "# comment line\n"
                              "mesh, n, seed, quality, iterations, output\n"
                              "parts/a.obj, 5, 7, best, 12,\n"
                              "\n"
                              "\"parts/with, comma.obj\",,,,, \"named/\"\"q\"\".txt\"\n"
                              "/abs/elsewhere/c.stl,2,,,,\r\n"
                              "../up/d.stl,4,,,,\n");
  auto items = listBatchItems(csv, quickOptions());
  ASSERT_TRUE(items.ok()) << items.error().message;
  ASSERT_EQ(items->size(), 4u);
  const BatchItem& a = (*items)[0];
  EXPECT_EQ(a.mesh, (fs::path(path("lists")) / "parts/a.obj").string());
  EXPECT_EQ(a.output, "parts/a.json");
  EXPECT_EQ(a.fit.num_spheres, 5);
  EXPECT_EQ(a.fit.seed, 7u);
  EXPECT_EQ(a.fit.quality, FitQuality::kBest);
  ASSERT_TRUE(a.fit.iterations.has_value());
  EXPECT_EQ(*a.fit.iterations, 12);
  EXPECT_EQ(a.origin, csv + ":3");
  const BatchItem& b = (*items)[1];  // empty fields keep the batch's values
  EXPECT_EQ(b.mesh, (fs::path(path("lists")) / "parts/with, comma.obj").string());
  EXPECT_EQ(b.output, "named/\"q\".txt");
  EXPECT_EQ(b.fit.num_spheres, 3);
  EXPECT_EQ(b.fit.seed, 1u);
  EXPECT_EQ(b.fit.quality, FitQuality::kFast);
  EXPECT_FALSE(b.fit.iterations.has_value());
  EXPECT_EQ((*items)[2].mesh, "/abs/elsewhere/c.stl");
  EXPECT_EQ((*items)[2].output, "c.json");  // outside the manifest's folder: the file name
  EXPECT_EQ((*items)[2].fit.num_spheres, 2);
  EXPECT_EQ((*items)[3].output, "d.json");
}

TEST_F(BatchTest, CsvManifestFromASpreadsheet) {
  // A byte order mark and CRLF line ends, as spreadsheet programs write them.
  const std::string csv = put("sheet.csv", "\xEF\xBB\xBFMesh,N\r\na.stl,7\r\n");
  auto items = listBatchItems(csv, quickOptions());
  ASSERT_TRUE(items.ok()) << items.error().message;
  ASSERT_EQ(items->size(), 1u);
  EXPECT_EQ(items->front().fit.num_spheres, 7);
  EXPECT_EQ(items->front().output, "a.json");
}

TEST_F(BatchTest, JsonlManifestWithPerItemOptions) {
  const std::string jl = put("m.jsonl",
                             "{\"mesh\": \"a.obj\", \"n\": 6, \"padding\": 0.25, \"method\": "
                             "\"kmeans\", \"restarts\": 2}\n"
                             "\n"
                             "{\"mesh\": \"sub/b.off\", \"seed\": null, \"decimation\": 0.5, "
                             "\"optimizer\": \"gradient\", \"init\": \"random\", \"points\": "
                             "\"3000\"}\n");
  auto items = listBatchItems(jl, quickOptions());
  ASSERT_TRUE(items.ok()) << items.error().message;
  ASSERT_EQ(items->size(), 2u);
  const FitRequest& a = (*items)[0].fit;
  EXPECT_EQ(a.num_spheres, 6);
  EXPECT_DOUBLE_EQ(a.padding, 0.25);
  EXPECT_EQ(a.method, FitMethod::kKMeans);
  EXPECT_EQ(a.restarts, std::optional<int>(2));
  const FitRequest& b = (*items)[1].fit;
  EXPECT_EQ((*items)[1].output, "sub/b.json");
  EXPECT_EQ(b.num_spheres, 3);
  EXPECT_EQ(b.seed, 1u);
  EXPECT_EQ(b.decimation, std::optional<double>(0.5));
  EXPECT_EQ(b.optimizer, SphereOptimizer::kGradient);
  EXPECT_EQ(b.init, FitInit::kRandom);
  EXPECT_EQ(b.points, 3000);
  EXPECT_EQ((*items)[1].origin, jl + ":3");
}

TEST_F(BatchTest, BadManifestLinesNameTheFileAndLine) {
  struct Case {
    const char* name;
    const char* text;
    const char* words;
  };
  const Case cases[] = {
      {"unknown.csv", "mesh,spheres\na.obj,3\n", ":1: unknown column 'spheres'"},
      {"nomesh.csv", "n\n3\n", ":1: the header has no 'mesh' column"},
      {"twice.csv", "mesh,n,N\na.obj,3,4\n", ":1: column 'N' given twice"},
      {"zero.csv", "mesh,n\na.obj,0\n", ":2: n '0': expected an integer from 1"},
      {"word.csv", "mesh,n\n\na.obj,abc\n", ":3: n 'abc': expected an integer"},
      {"fields.csv", "mesh,n\na.obj,3,4\n", ":2: expected 2 fields as in the header, found 3"},
      {"quote.csv", "mesh,n\n\"a.obj,3\n", ":2: unterminated quoted field"},
      {"empty.csv", "mesh,n\n,3\n", ":2: the mesh path is empty"},
      {"quality.csv", "mesh,quality\na.obj,great\n", ":2: quality 'great': expected fast"},
      {"padding.csv", "mesh,padding\na.obj,-1\n",
       ":2: padding '-1': expected a number from 0 to 1e+30"},
      {"out.csv", "mesh,output\na.obj,../x.json\n", ":2: output '../x.json': expected a relative"},
      {"outext.csv", "mesh,output\na.obj,x.obj\n", ":2: output 'x.obj': the extension"},
      {"same.csv", "mesh,n\na.obj,3\na.obj,4\n", ":3: writes a.obj.json as"},
      {"json.jsonl", "{\"mesh\": \"a.obj\"}\n{\"mesh\": \"b.obj\",\n", ":2: not valid JSON"},
      {"array.jsonl", "[1, 2]\n", ":1: expected a JSON object"},
      {"key.jsonl", "{\"mesh\": \"a.obj\", \"colour\": 1}\n", ":1: unknown key \"colour\""},
      {"nomesh.jsonl", "{\"n\": 3}\n", ":1: no \"mesh\" key"},
      {"float.jsonl", "{\"mesh\": \"a.obj\", \"n\": 3.5}\n", ":1: n '3.5': expected an integer"},
      {"bool.jsonl", "{\"mesh\": \"a.obj\", \"seed\": true}\n",
       ":1: \"seed\": expected a string or a number"},
  };
  for (const Case& c : cases) {
    const std::string p = put(c.name, c.text);
    SCOPED_TRACE(c.name);
    test::expectError(listBatchItems(p, quickOptions()), ErrorCode::kInvalidData, p, c.words);
  }
}

// The item's spheres are those of fitSpheres with the options of `sphereset fit`, on the solid
// loadSolid makes; the file is the one writeSpheres writes.
TEST_F(BatchTest, ItemGivesTheSpheresOfTheFit) {
  box("in/part/box.off", 2.0);
  BatchOptions o = quickOptions();
  o.fit.seed = 5;
  auto items = listBatchItems(path("in"), o);
  ASSERT_TRUE(items.ok() && items->size() == 1);
  const BatchItem& item = items->front();
  const BatchItemReport r = runBatchItem(item, path("out"), o);
  ASSERT_EQ(r.status, BatchStatus::kOk) << r.error;
  EXPECT_EQ(r.output, "part/box.json");
  EXPECT_EQ(r.repair, "none");

  auto solid = loadSolid(item.mesh, o.repair);
  ASSERT_TRUE(solid.ok());
  const SolidIndex index(solid->repair.solid);
  FitOptions fo = fitOptionsFor(item.fit);
  EXPECT_EQ(fo.seed, 5u);
  EXPECT_EQ(fo.max_iterations, 20);  // the fast preset
  auto fit = fitSpheres(index, fo);
  ASSERT_TRUE(fit.ok());
  SphereFileMeta meta;
  meta.name = "box";
  meta.source_mesh = item.mesh;
  EXPECT_EQ(test::readFile(path("out/part/box.json")),
            formatSpheres(SphereFormat::kJson, fit->spheres, meta));
  EXPECT_EQ(r.spheres, 3);
  EXPECT_EQ(r.num_spheres, 3);
  const EvalResult ev = *evaluateSpheres(index, fit->spheres, fitCheckEvalOptions(5));
  EXPECT_DOUBLE_EQ(r.er_sum, fit->energy / ev.mesh_volume);
  EXPECT_DOUBLE_EQ(r.er_union, ev.er_union);
  EXPECT_EQ(r.covered, ev.surface_covered && ev.interior_covered);
  EXPECT_TRUE(r.covered);
  EXPECT_GT(r.seconds, 0.0);
  EXPECT_EQ(r.fingerprint, batchFingerprint(item, o).value());
}

TEST_F(BatchTest, ToleranceColumnsChooseTheCount) {
  // A manifest's max_protrusion / max_er columns: the item's count is the fewest that meet its
  // tolerance (fitToTolerance on the same solid gives the same spheres); its line's value wins
  // over the batch's; n with a tolerance on one line is refused; a tolerance no count meets is
  // the item's error and writes nothing.
  box("a.off");
  box("b.off", 2.0);
  put("list.csv", "mesh,max_protrusion,max_spheres\na.off,12%,16\nb.off,,\n");
  BatchOptions o = quickOptions();
  ASSERT_TRUE(setToleranceOption(&o.tolerance, "max_er", "2").ok());
  auto items = listBatchItems(path("list.csv"), o);
  ASSERT_TRUE(items.ok()) << items.error().message;
  ASSERT_EQ(items->size(), 2u);
  EXPECT_DOUBLE_EQ((*items)[0].tolerance.max_protrusion_fraction, 0.12);
  EXPECT_EQ((*items)[0].tolerance.max_spheres, 16);
  EXPECT_EQ((*items)[1].tolerance.max_er, 2.0);  // the batch's
  for (const BatchItem& item : *items) {
    const BatchItemReport r = runBatchItem(item, path("out"), o);
    ASSERT_EQ(r.status, BatchStatus::kOk) << r.error;
    EXPECT_EQ(r.num_spheres, 0);  // no n asked: the tolerance chose
    EXPECT_TRUE(r.tolerance_met && r.covered);
    auto written = readSpheres(path("out/" + item.output));
    ASSERT_TRUE(written.ok());
    EXPECT_EQ(static_cast<int>(written->size()), r.spheres);
    auto mesh = loadMesh(item.mesh);
    ASSERT_TRUE(mesh.ok());
    const SolidIndex index(mesh->mesh);
    auto t = fitToTolerance(index, item.fit, item.tolerance);
    ASSERT_TRUE(t.ok() && t->met);
    EXPECT_EQ(t->n, r.spheres);
    EXPECT_EQ(t->eval.protrusion, r.protrusion);
    // The report line carries both fields and reads back.
    auto back = parseReportLine(reportLine(r));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->protrusion, r.protrusion);
    EXPECT_TRUE(back->tolerance_met);
  }
  put("both.csv", "mesh,n,max_er\na.off,4,1\n");
  test::expectError(listBatchItems(path("both.csv"), quickOptions()), ErrorCode::kInvalidData,
                    "both.csv", ":2: n and a tolerance");
  // A line's own cap with no limit (its own or the batch's) would cap nothing: refused.
  put("cap.csv", "mesh,n,max_spheres\na.off,4,8\n");
  test::expectError(listBatchItems(path("cap.csv"), quickOptions()), ErrorCode::kInvalidData,
                    "cap.csv", ":2: max_spheres goes with a tolerance");
  // The batch's cap binds the lines with a limit; with a limit on no line, or for a folder with
  // no limit, it and best effort are refused, as the batch's n with its limit is.
  BatchOptions capped = quickOptions();
  ASSERT_TRUE(setToleranceOption(&capped.tolerance, "max_spheres", "8").ok());
  put("mixed.csv", "mesh,n,max_er\na.off,4,\nb.off,,1\n");
  auto mixed = listBatchItems(path("mixed.csv"), capped);
  ASSERT_TRUE(mixed.ok()) << mixed.error().message;
  EXPECT_FALSE((*mixed)[0].tolerance.active());
  EXPECT_EQ((*mixed)[1].tolerance.max_spheres, 8);
  put("fixed.csv", "mesh,n\na.off,4\n");
  test::expectError(listBatchItems(path("fixed.csv"), capped), ErrorCode::kInvalidArgument,
                    "fixed.csv: max_spheres goes with a tolerance", "(no line gives one)");
  test::expectError(listBatchItems(path("."), capped), ErrorCode::kInvalidArgument, "max_spheres",
                    "goes with a tolerance");
  BatchOptions effort = quickOptions();
  effort.best_effort = true;
  test::expectError(listBatchItems(path("."), effort), ErrorCode::kInvalidArgument, "best_effort",
                    "goes with a tolerance");
  BatchOptions both = quickOptions();
  ASSERT_TRUE(setFitRequestOption(&both.fit, "n", "4").ok());
  ASSERT_TRUE(setToleranceOption(&both.tolerance, "max_er", "1").ok());
  test::expectError(listBatchItems(path("fixed.csv"), both), ErrorCode::kInvalidArgument,
                    "n and a tolerance", "exclude each other");
  BatchItem never = (*items)[0];
  never.output = "never.json";
  never.tolerance = {};
  ASSERT_TRUE(setToleranceOption(&never.tolerance, "max_protrusion", "0.0000001").ok());
  ASSERT_TRUE(setToleranceOption(&never.tolerance, "max_spheres", "2").ok());
  const BatchItemReport r = runBatchItem(never, path("out"), o);
  EXPECT_EQ(r.status, BatchStatus::kError);
  EXPECT_NE(r.error.find("no count up to 2 meets the tolerance"), std::string::npos) << r.error;
  EXPECT_FALSE(r.tolerance_met);
  EXPECT_FALSE(fs::exists(path("out/never.json")));
  // With best_effort the best count is written (status ok, tolerance not met), the same spheres
  // fitToTolerance gives as its best; a later run is up to date only if it also takes the best
  // effort, and without it the item is an error again.
  BatchOptions best = o;
  best.best_effort = true;
  const BatchItemReport b = runBatchItem(never, path("out"), best);
  ASSERT_EQ(b.status, BatchStatus::kOk) << b.error;
  EXPECT_FALSE(b.tolerance_met);
  auto written = readSpheres(path("out/never.json"));
  ASSERT_TRUE(written.ok());
  auto mesh = loadMesh(never.mesh);
  ASSERT_TRUE(mesh.ok());
  const SolidIndex never_index(mesh->mesh);
  auto t = fitToTolerance(never_index, never.fit, never.tolerance);
  ASSERT_TRUE(t.ok() && !t->met);
  EXPECT_EQ(static_cast<int>(written->size()), t->n);
  EXPECT_EQ(b.spheres, t->n);
  EXPECT_EQ(b.protrusion, t->eval.protrusion);
  EXPECT_GT(b.protrusion, 0.0000001);
  auto back = parseReportLine(reportLine(b));
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_FALSE(back->tolerance_met);
  EXPECT_TRUE(batchItemDone(never, path("out"), best));
  EXPECT_FALSE(batchItemDone(never, path("out"), o));
  EXPECT_EQ(processBatchItem(never, path("out"), best).status, BatchStatus::kSkipped);
  EXPECT_EQ(processBatchItem(never, path("out"), o).status, BatchStatus::kError);
}

TEST_F(BatchTest, ItemRunsInAnArenaWithTheSameResult) {
  const std::string mesh = box("box.off");
  BatchOptions o = quickOptions();
  BatchItem item{mesh, "one.txt", o.fit, "test", {}};
  ASSERT_EQ(runBatchItem(item, path("out"), o).status, BatchStatus::kOk);
  o.threads = 1;
  item.output = "two.txt";
  ASSERT_EQ(runBatchItem(item, path("out"), o).status, BatchStatus::kOk);
  EXPECT_EQ(test::readFile(path("out/one.txt")), test::readFile(path("out/two.txt")));
}

TEST_F(BatchTest, FailedItemsAreReportedNotThrown) {
  const std::string garbage = put("bad.stl", "not a mesh at all");
  BatchOptions o = quickOptions();
  BatchItem item{garbage, "bad.json", o.fit, "test", {}};
  BatchItemReport r = runBatchItem(item, path("out"), o);
  EXPECT_EQ(r.status, BatchStatus::kError);
  EXPECT_EQ(r.error_code, ErrorCode::kUnreadable);
  EXPECT_NE(r.error.find("bad.stl"), std::string::npos) << r.error;
  EXPECT_TRUE(std::isnan(r.er_sum));
  EXPECT_FALSE(fs::exists(path("out/bad.json")));
  EXPECT_FALSE(batchItemDone(item, path("out"), o));

  // An open sheet with the repair off is not a solid.
  const std::string sheet =
      put("sheet.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  o.repair.enabled = false;
  r = runBatchItem(BatchItem{sheet, "sheet.json", o.fit, "test", {}}, path("out"), o);
  EXPECT_EQ(r.status, BatchStatus::kError);
  EXPECT_EQ(r.error_code, ErrorCode::kNotSolid);
  EXPECT_NE(r.error.find("sheet.off"), std::string::npos) << r.error;

  // More spheres than points.
  o.repair.enabled = true;
  BatchItem many{box("box.off"), "many.json", o.fit, "test", {}};
  many.fit.points = 50;
  many.fit.num_spheres = 500;
  r = runBatchItem(many, path("out"), o);
  EXPECT_EQ(r.status, BatchStatus::kError);
  EXPECT_NE(r.error.find("box.off: "), std::string::npos) << r.error;
  EXPECT_EQ(reportLine(r).find('\n'), std::string::npos);
}

// Resuming used to keep the spheres of a glTF whose .bin had changed ("skipped", covered,
// while eval said not covered): the files a mesh references are part of what is up to date.
TEST_F(BatchTest, ChangedReferencedFilesMakeTheItemRunAgain) {
  put("in/tet.gltf", test::tetrahedronGltf("tet.bin"));
  put("in/tet.bin", test::tetrahedronBin(1.0f));
  const BatchOptions o = quickOptions();
  auto items = listBatchItems(path("in"), o);
  ASSERT_TRUE(items.ok()) << items.error().message;
  ASSERT_EQ(items->size(), 1u);  // the buffer is not an item of its own
  const BatchItem item = items->front();
  const std::string out = path("out");
  const BatchItemReport first = processBatchItem(item, out, o);
  ASSERT_EQ(first.status, BatchStatus::kOk) << first.error;
  EXPECT_TRUE(batchItemDone(item, out, o));
  put("in/tet.bin", test::tetrahedronBin(2.0f));
  EXPECT_FALSE(batchItemDone(item, out, o));
  const BatchItemReport again = processBatchItem(item, out, o);
  EXPECT_EQ(again.status, BatchStatus::kOk);
  EXPECT_TRUE(again.covered);
  EXPECT_TRUE(batchItemDone(item, out, o));
}

TEST_F(BatchTest, UpToDateItemsAreSkippedAndChangedOnesRunAgain) {
  box("in/box.off");
  const BatchOptions o = quickOptions();
  auto items = listBatchItems(path("in"), o);
  ASSERT_TRUE(items.ok() && items->size() == 1);
  const BatchItem item = items->front();
  const std::string out = path("out");
  EXPECT_FALSE(batchItemDone(item, out, o));
  const BatchItemReport first = processBatchItem(item, out, o);
  ASSERT_EQ(first.status, BatchStatus::kOk) << first.error;
  EXPECT_TRUE(batchItemDone(item, out, o));

  // A second run skips it and reports the first run's figures.
  const BatchItemReport again = processBatchItem(item, out, o);
  EXPECT_EQ(again.status, BatchStatus::kSkipped);
  EXPECT_EQ(again.er_sum, first.er_sum);
  EXPECT_EQ(again.seconds, first.seconds);
  EXPECT_EQ(again.fingerprint, first.fingerprint);
  BatchOptions no_resume = o;
  no_resume.resume = false;
  EXPECT_EQ(processBatchItem(item, out, no_resume).status, BatchStatus::kOk);

  // Changed options: not up to date.
  BatchItem other = item;
  other.fit.seed = 2;
  EXPECT_FALSE(batchItemDone(other, out, o));
  other = item;
  other.fit.num_spheres = 4;
  EXPECT_FALSE(batchItemDone(other, out, o));
  other = item;
  other.fit.quality = FitQuality::kDefault;
  EXPECT_FALSE(batchItemDone(other, out, o));
  other = item;
  other.fit.padding = 0.01;
  EXPECT_FALSE(batchItemDone(other, out, o));
  BatchOptions changed = o;
  changed.repair.fill_cavities = false;
  EXPECT_FALSE(batchItemDone(item, out, changed));
  // The same options spelled differently (the fast preset's own rounds): up to date.
  other = item;
  other.fit.iterations = 20;
  EXPECT_TRUE(batchItemDone(other, out, o));
  EXPECT_EQ(processBatchItem(other, out, o).status, BatchStatus::kSkipped);

  // A changed sphere file or mesh, or a missing record: not up to date.
  const std::string sphere_file = path("out/box.json");
  const std::string kept = test::readFile(sphere_file);
  std::ofstream(sphere_file, std::ios::app) << " ";
  EXPECT_FALSE(batchItemDone(item, out, o));
  std::ofstream(sphere_file, std::ios::trunc) << kept;
  EXPECT_TRUE(batchItemDone(item, out, o));
  box("in/box.off", 1.5);
  EXPECT_FALSE(batchItemDone(item, out, o));
  EXPECT_EQ(processBatchItem(item, out, o).status, BatchStatus::kOk);
  EXPECT_TRUE(batchItemDone(item, out, o));
  fs::remove(path("out/.sphereset-batch/box.json.json"));
  EXPECT_FALSE(batchItemDone(item, out, o));
  EXPECT_FALSE(skippedBatchItem(item, out, o).has_value());
}

// A failed run of an item forgets the earlier result: its sphere file stays but is not taken as
// up to date.
TEST_F(BatchTest, FailedRunOfADoneItemIsNotUpToDate) {
  const std::string mesh = box("box.off");
  const BatchOptions o = quickOptions();
  const BatchItem item{mesh, "box.json", o.fit, "test", {}};
  ASSERT_EQ(runBatchItem(item, path("out"), o).status, BatchStatus::kOk);
  ASSERT_TRUE(batchItemDone(item, path("out"), o));
  put("box.off", "garbage");
  EXPECT_EQ(runBatchItem(item, path("out"), o).status, BatchStatus::kError);
  box("box.off");
  EXPECT_TRUE(fs::exists(path("out/box.json")));
  EXPECT_FALSE(batchItemDone(item, path("out"), o));
}

}  // namespace
}  // namespace sphereset
