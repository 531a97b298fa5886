// One CSV row per centre weighting for a sphere set moved through a motion: a skinned asset's
// clip (--animation ASSET) or a mesh bent by a smooth two-bone blend (--bend MESH: the part
// above the middle of the mesh's height turns about the horizontal x axis through the middle,
// the bone weights rising smoothly over the middle `band` of the height, up to `angle` degrees
// in `frames` steps). Columns: see kHeader. With --fresh, a fresh fit of as many spheres per
// frame (default options) gives the E_r the rebound is compared with.
//
//   animate_table --animation ASSET SPHERES [--fresh]
//   animate_table --bend MESH SPHERES [--frames 8] [--angle 45] [--band 0.4] [--fresh]
//   animate_table --header
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "sphereset/animate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"

using namespace sphereset;

namespace {

constexpr const char* kHeader =
    "source,vertices,spheres,weighting,frames,weights_s,update_ms,covered_fixed,"
    "fraction_covered_fixed,mean_er_fixed,max_gap,mean_er_rebound,covered_rebound,"
    "mean_radius_growth,max_radius_growth,mean_er_fresh,fresh_s,eval_s,rebound_s,frames_crossing";

int die(const std::string& m) {
  std::fprintf(stderr, "animate_table: %s\n", m.c_str());
  return 1;
}

struct Motion {
  Mesh rest;
  SkinWeights skin;
  std::vector<AnimationFrame> frames;
};

Motion bend(const Mesh& rest, int frames, double angle_deg, double band) {
  Motion m;
  m.rest = rest;
  const Aabb box = boundingBox(rest);
  const double lo = box.min.y(), h = box.max.y() - box.min.y();
  const double mid = lo + 0.5 * h;
  m.skin.bones = 2;
  m.skin.vertex_weights.resize(static_cast<Eigen::Index>(rest.vertices.size()), 2);
  for (size_t i = 0; i < rest.vertices.size(); ++i) {
    const double s =
        std::clamp((rest.vertices[i].y() - (mid - 0.5 * band * h)) / (band * h), 0.0, 1.0);
    const double w = s * s * (3.0 - 2.0 * s);  // smoothstep
    m.skin.vertex_weights(static_cast<Eigen::Index>(i), 0) = 1.0 - w;
    m.skin.vertex_weights(static_cast<Eigen::Index>(i), 1) = w;
  }
  const Vec3 pivot(box.center().x(), mid, box.center().z());
  for (int f = 0; f < frames; ++f) {
    const double a = angle_deg * (frames > 1 ? double(f) / (frames - 1) : 1.0) * M_PI / 180.0;
    AnimationFrame fr;
    fr.time = f;
    fr.bones = {Eigen::Affine3d::Identity(),
                Eigen::Affine3d(Eigen::Translation3d(pivot) * Eigen::AngleAxisd(a, Vec3::UnitX()) *
                                Eigen::Translation3d(-pivot))};
    fr.vertices = skinPoints(rest.vertices, m.skin.vertex_weights, fr.bones).value();
    m.frames.push_back(std::move(fr));
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--header") == 0) {
    std::printf("%s\n", kHeader);
    return 0;
  }
  if (argc < 4) return die("usage: animate_table (--animation ASSET | --bend MESH) SPHERES ...");
  const std::string mode = argv[1], source = argv[2], spheres_path = argv[3];
  int frames = 8;
  double angle = 45.0, band = 0.4;
  bool fresh = false;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--fresh")
      fresh = true;
    else if (a == "--frames" && i + 1 < argc)
      frames = std::stoi(argv[++i]);
    else if (a == "--angle" && i + 1 < argc)
      angle = std::stod(argv[++i]);
    else if (a == "--band" && i + 1 < argc)
      band = std::stod(argv[++i]);
    else
      return die("unknown argument " + a);
  }
  auto spheres = readSpheres(spheres_path);
  if (!spheres) return die(spheres.error().message);
  Motion m;
  if (mode == "--animation") {
    auto anim = loadAnimation(source);
    if (!anim) return die(anim.error().message);
    m.rest = anim->asset.rest;
    m.skin = anim->asset.skin;
    m.frames = anim->frames;
  } else if (mode == "--bend") {
    auto mesh = loadMesh(source);
    if (!mesh) return die(mesh.error().message);
    m = bend(mesh->mesh, frames, angle, band);
  } else {
    return die("unknown mode " + mode);
  }
  // The fresh fits, once per frame (they do not depend on the weighting).
  double er_fresh = 0.0, fresh_s = 0.0;
  if (fresh) {
    for (const AnimationFrame& f : m.frames) {
      const auto t0 = std::chrono::steady_clock::now();
      const Mesh deformed{f.vertices, m.rest.triangles};
      const SolidIndex index(deformed);
      FitOptions fo;
      fo.num_spheres = static_cast<int>(spheres->size());
      auto fit = fitSpheres(index, fo);
      if (!fit) return die(fit.error().message);
      er_fresh += fit->energy / signedVolume(deformed);
      fresh_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    er_fresh /= double(m.frames.size());
    fresh_s /= double(m.frames.size());
  }
  for (CentreWeighting w : {CentreWeighting::kMeanValue, CentreWeighting::kBones}) {
    AnimateOptions o;
    o.weighting = w;
    o.rebound = true;
    auto r = animateSpheres(m.rest, *spheres, m.frames, o, &m.skin);
    if (!r) return die(r.error().message);
    double ev = 0.0, rb = 0.0;
    double upd = 0.0, er = 0.0, erb = 0.0, gap = 0.0, growth = 0.0, max_growth = 0.0;
    int64_t covered_rb = 0;
    for (const AnimateFrameResult& f : r->frames) {
      upd += f.update_seconds;
      ev += f.eval_seconds;
      rb += f.rebound_seconds;
      er += f.er;
      erb += f.er_rebound;
      gap = std::max(gap, f.max_gap);
      growth += f.radius_growth;
      max_growth = std::max(max_growth, f.max_radius_growth);
      covered_rb += f.rebound_covered;
    }
    const double nf = double(r->frames.size());
    const std::string name = source.substr(source.find_last_of('/') + 1);
    std::printf(
        "%s,%zu,%zu,%s,%zu,%.4f,%.5f,%lld,%.3f,%.4f,%.3g,%.4f,%lld,%.4f,%.4f,%s,%s,%.3f,%.3f,%"
        "lld\n",
        name.c_str(), m.rest.vertices.size(), spheres->size(),
        w == CentreWeighting::kBones ? "bones" : "mean_value", r->frames.size(), r->weights_seconds,
        1e3 * upd / nf, static_cast<long long>(r->frames_covered), double(r->frames_covered) / nf,
        er / nf, gap, erb / nf, static_cast<long long>(covered_rb), growth / nf, max_growth,
        fresh ? std::to_string(er_fresh).c_str() : "", fresh ? std::to_string(fresh_s).c_str() : "",
        ev / nf, rb / nf, static_cast<long long>(r->frames_crossing));
    std::fflush(stdout);
  }
  return 0;
}
