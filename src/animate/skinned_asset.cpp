// Skinned, animated assets read through assimp (aiMesh bones, aiAnimation channels): the bind
// pose as the rest mesh, per-vertex bone weights, and linear blend skinning evaluated at the
// clip's keyframe times or at a fixed rate. Keys are interpolated linearly (positions,
// scalings) and spherically (rotations), each node's local transform being T·R·S.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "io/companion_io.hpp"
#include "mesh/weld.hpp"
#include "sphereset/animate.hpp"
#include "sphereset/limits.hpp"
#include "util/number_text.hpp"

namespace sphereset {
namespace {

// Ticks per second when the file gives none (assimp's documented fallback).
constexpr double kDefaultTicksPerSecond = 25.0;
// Key times closer than this many ticks are one keyframe time.
constexpr double kSameKeyTicks = 1e-9;

Eigen::Affine3d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) e(r, c) = m[r][c];
  return Eigen::Affine3d(e);
}

template <class Key>
size_t keyBefore(const Key* keys, unsigned n, double t) {
  size_t i = 0;
  while (i + 1 < n && keys[i + 1].mTime <= t) ++i;
  return i;
}

aiVector3D lerpKeys(const aiVectorKey* k, unsigned n, double t, aiVector3D fallback) {
  if (n == 0) return fallback;
  const size_t i = keyBefore(k, n, t);
  if (i + 1 >= n || t <= k[i].mTime) return k[i].mValue;
  const double a = (t - k[i].mTime) / (k[i + 1].mTime - k[i].mTime);
  return k[i].mValue + static_cast<ai_real>(a) * (k[i + 1].mValue - k[i].mValue);
}

aiQuaternion slerpKeys(const aiQuatKey* k, unsigned n, double t, aiQuaternion fallback) {
  if (n == 0) return fallback;
  const size_t i = keyBefore(k, n, t);
  if (i + 1 >= n || t <= k[i].mTime) return k[i].mValue;
  const double a = (t - k[i].mTime) / (k[i + 1].mTime - k[i].mTime);
  aiQuaternion q;
  aiQuaternion::Interpolate(q, k[i].mValue, k[i + 1].mValue, static_cast<ai_real>(a));
  return q.Normalize();
}

// Global transforms of every node at tick t of `anim` (null: the file's static transforms).
void globalTransforms(const aiNode* node, const aiMatrix4x4& parent,
                      const std::map<std::string, const aiNodeAnim*>& channels, double t,
                      std::map<const aiNode*, aiMatrix4x4>* out) {
  aiMatrix4x4 local = node->mTransformation;
  const auto ch = channels.find(node->mName.C_Str());
  if (ch != channels.end()) {
    aiVector3D s0, p0;
    aiQuaternion r0;
    local.Decompose(s0, r0, p0);
    const aiNodeAnim* c = ch->second;
    const aiVector3D p = lerpKeys(c->mPositionKeys, c->mNumPositionKeys, t, p0);
    const aiQuaternion r = slerpKeys(c->mRotationKeys, c->mNumRotationKeys, t, r0);
    const aiVector3D s = lerpKeys(c->mScalingKeys, c->mNumScalingKeys, t, s0);
    aiMatrix4x4 ms, mt;
    aiMatrix4x4::Scaling(s, ms);
    aiMatrix4x4::Translation(p, mt);
    local = mt * aiMatrix4x4(r.GetMatrix()) * ms;
  }
  const aiMatrix4x4 g = parent * local;
  (*out)[node] = g;
  for (unsigned i = 0; i < node->mNumChildren; ++i)
    globalTransforms(node->mChildren[i], g, channels, t, out);
}

// One "bone" of the skin: a transform from the bind pose to the pose at time t. Bones of the
// asset are (mesh instance, aiBone) pairs, G_bone(t) · offset · M⁻¹ with M the mesh node's
// bind transform; vertices no aiBone moves follow their mesh node rigidly, as the bone
// M(t) · M⁻¹.
struct BoneDef {
  const aiNode* node = nullptr;  // the bone's node, or the mesh node for the rigid bone
  aiMatrix4x4 offset;            // identity for the rigid bone
  aiMatrix4x4 mesh_bind_inverse;
  std::string name;
};

struct RawSkin {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::vector<std::vector<std::pair<int32_t, double>>> weights;  // per raw vertex
  std::vector<bool> rigid;  // per raw vertex: no aiBone moves it (it follows its mesh node)
  std::vector<BoneDef> bones;
};

void collect(const aiScene* scene, const aiNode* node,
             const std::map<const aiNode*, aiMatrix4x4>& bind,
             const std::map<std::string, const aiNode*>& by_name, RawSkin* raw) {
  const aiMatrix4x4& m = bind.at(node);
  aiMatrix4x4 m_inv = m;
  m_inv.Inverse();
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
    const auto base = static_cast<int32_t>(raw->vertices.size());
    std::vector<std::vector<std::pair<int32_t, double>>> w(mesh->mNumVertices);
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
      const aiBone* bone = mesh->mBones[b];
      const auto it = by_name.find(bone->mName.C_Str());
      if (it == by_name.end()) continue;
      const auto id = static_cast<int32_t>(raw->bones.size());
      raw->bones.push_back({it->second, bone->mOffsetMatrix, m_inv, bone->mName.C_Str()});
      for (unsigned q = 0; q < bone->mNumWeights; ++q) {
        const aiVertexWeight& vw = bone->mWeights[q];
        if (vw.mVertexId < mesh->mNumVertices && vw.mWeight > 0.0f)
          w[vw.mVertexId].emplace_back(id, vw.mWeight);
      }
    }
    const auto rigid = static_cast<int32_t>(raw->bones.size());
    raw->bones.push_back(
        {node, aiMatrix4x4(), m_inv, std::string(node->mName.C_Str()) + "(rigid)"});
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D p = m * mesh->mVertices[i];
      raw->vertices.emplace_back(p.x, p.y, p.z);
      double sum = 0.0;
      for (const auto& [b, x] : w[i]) sum += x;
      if (sum > 0.0) {
        for (auto& bw : w[i]) bw.second /= sum;
        raw->weights.push_back(std::move(w[i]));
        raw->rigid.push_back(false);
      } else {
        raw->weights.push_back({{rigid, 1.0}});
        raw->rigid.push_back(true);
      }
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      for (unsigned q = 1; q + 1 < face.mNumIndices; ++q) {
        if (face.mIndices[0] >= mesh->mNumVertices || face.mIndices[q] >= mesh->mNumVertices ||
            face.mIndices[q + 1] >= mesh->mNumVertices)
          continue;
        raw->triangles.push_back({base + static_cast<int32_t>(face.mIndices[0]),
                                  base + static_cast<int32_t>(face.mIndices[q]),
                                  base + static_cast<int32_t>(face.mIndices[q + 1])});
      }
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c)
    collect(scene, node->mChildren[c], bind, by_name, raw);
}

void nameNodes(const aiNode* node, std::map<std::string, const aiNode*>* out) {
  out->emplace(node->mName.C_Str(), node);
  for (unsigned c = 0; c < node->mNumChildren; ++c) nameNodes(node->mChildren[c], out);
}

}  // namespace

Expected<LoadedAnimation> loadAnimation(const std::string& path,
                                        const SkinnedLoadOptions& options) {
  if (Status st = checkTableValue(skinnedLoadOptionTable(), "animation", "fps", options.fps); !st)
    return st.error();
  if (Status st = detail::checkBeforeAssimp(path); !st) return st.error();
  Assimp::Importer importer;
  importer.SetIOHandler(new detail::CompanionIOSystem(path));  // owned by the importer
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown format";
    return Error{ErrorCode::kUnreadable, path + ": cannot be read as an asset (" + why + ")"};
  }
  if (scene->mNumAnimations == 0)
    return Error{ErrorCode::kInvalidData, path + ": the asset has no animation"};
  LoadedAnimation out;
  for (unsigned a = 0; a < scene->mNumAnimations; ++a)
    out.asset.clips.emplace_back(scene->mAnimations[a]->mName.C_Str());
  const aiAnimation* anim = scene->mAnimations[0];
  if (!options.clip.empty()) {
    anim = nullptr;
    for (unsigned a = 0; a < scene->mNumAnimations; ++a)
      if (out.asset.clips[a] == options.clip) anim = scene->mAnimations[a];
    if (!anim) {
      std::string list;
      for (const std::string& c : out.asset.clips)
        list +=
            (list.empty() ? "" : ", ") + (c.empty() ? std::string("one unnamed") : "'" + c + "'");
      return Error{ErrorCode::kInvalidArgument,
                   path + ": no clip '" + options.clip + "' (it has " + list + ")"};
    }
  }
  out.clip = anim->mName.C_Str();

  std::map<std::string, const aiNode*> by_name;
  nameNodes(scene->mRootNode, &by_name);
  std::map<const aiNode*, aiMatrix4x4> bind;
  globalTransforms(scene->mRootNode, aiMatrix4x4(), {}, 0.0, &bind);
  RawSkin raw;
  collect(scene, scene->mRootNode, bind, by_name, &raw);
  if (raw.triangles.empty())
    return Error{ErrorCode::kInvalidData, path + ": the asset contains no triangles"};

  // Weld exactly coincident positions (as loadMesh does), then clean; the cleaned vertices are
  // matched back to the welded ones by position.
  std::vector<Vec3> welded;
  const std::vector<int32_t> map = detail::weldVertices(raw.vertices, 0.0, &welded);
  std::vector<Triangle> tris = raw.triangles;
  for (Triangle& t : tris)
    for (int32_t& v : t) v = map[static_cast<size_t>(v)];
  // The weights of a welded vertex: the mean of those of its copies that some aiBone moves (a
  // file may weight only some copies of a split vertex), else its first copy's rigid bone.
  std::vector<int32_t> first_raw(welded.size(), -1);
  std::vector<std::map<int32_t, double>> merged(welded.size());
  std::vector<int> weighted(welded.size(), 0);
  for (size_t i = 0; i < map.size(); ++i) {
    const auto w = static_cast<size_t>(map[i]);
    if (first_raw[w] < 0) first_raw[w] = static_cast<int32_t>(i);
    if (raw.rigid[i]) continue;
    ++weighted[w];
    for (const auto& [b, x] : raw.weights[i]) merged[w][b] += x;
  }
  for (size_t w = 0; w < welded.size(); ++w) {
    if (weighted[w] == 0) {
      for (const auto& [b, x] : raw.weights[static_cast<size_t>(first_raw[w])]) merged[w][b] += x;
    } else {
      for (auto& bx : merged[w]) bx.second /= weighted[w];
    }
  }
  auto cleaned = cleanMesh(welded, tris, LoadOptions{}, path);
  if (!cleaned) return cleaned.error();
  out.asset.rest = std::move(cleaned->mesh);
  std::map<std::array<double, 3>, int32_t> by_pos;
  for (size_t i = 0; i < welded.size(); ++i)
    by_pos.emplace(std::array<double, 3>{welded[i].x(), welded[i].y(), welded[i].z()},
                   static_cast<int32_t>(i));
  const size_t nv = out.asset.rest.vertices.size();
  std::vector<int32_t> source(nv);
  for (size_t i = 0; i < nv; ++i) {
    const Vec3& p = out.asset.rest.vertices[i];
    const auto it = by_pos.find({p.x(), p.y(), p.z()});
    if (it == by_pos.end())
      return Error{ErrorCode::kInvalidData, path + ": a cleaned vertex has no source vertex"};
    source[i] = it->second;
  }
  if (raw.bones.size() > static_cast<size_t>(limits::kMaxBones))
    return Error{ErrorCode::kInvalidData, path + ": " + std::to_string(raw.bones.size()) +
                                              " bones (the limit is " +
                                              std::to_string(limits::kMaxBones) + ")"};
  if (Status st = limits::checkArray(
          path + ": the skin of " + std::to_string(nv) + " vertices and " +
              std::to_string(raw.bones.size()) + " bones",
          static_cast<double>(nv), sizeof(double) * static_cast<double>(raw.bones.size()));
      !st)
    return st.error();
  const auto nb = static_cast<int>(raw.bones.size());
  out.asset.skin.bones = nb;
  out.asset.skin.vertex_weights = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(nv), nb);
  for (size_t i = 0; i < nv; ++i)
    for (const auto& [b, w] : merged[static_cast<size_t>(source[i])])
      out.asset.skin.vertex_weights(static_cast<Eigen::Index>(i), b) += w;
  for (const BoneDef& b : raw.bones) out.asset.bone_names.push_back(b.name);

  // Frame times in ticks: the union of the clip's key times, or a fixed rate.
  std::map<std::string, const aiNodeAnim*> channels;
  std::vector<double> keys;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) {
    const aiNodeAnim* ch = anim->mChannels[c];
    channels[ch->mNodeName.C_Str()] = ch;
    for (unsigned k = 0; k < ch->mNumPositionKeys; ++k) keys.push_back(ch->mPositionKeys[k].mTime);
    for (unsigned k = 0; k < ch->mNumRotationKeys; ++k) keys.push_back(ch->mRotationKeys[k].mTime);
    for (unsigned k = 0; k < ch->mNumScalingKeys; ++k) keys.push_back(ch->mScalingKeys[k].mTime);
  }
  const double tps = anim->mTicksPerSecond > 0.0 ? anim->mTicksPerSecond : kDefaultTicksPerSecond;
  double duration = anim->mDuration;
  if (!keys.empty()) duration = std::max(duration, *std::max_element(keys.begin(), keys.end()));
  out.duration = duration / tps;
  std::vector<double> ticks;
  if (options.fps > 0.0) {
    const double step = tps / options.fps;
    // Checked before any frame is made: the count, then the memory of the frames' vertices.
    const double count = std::floor((duration + kSameKeyTicks) / step) + 1.0;
    if (!(count <= static_cast<double>(limits::kMaxFrames)))
      return Error{ErrorCode::kInvalidArgument,
                   path + ": " + detail::numberText(out.duration) + " s at fps " +
                       detail::numberText(options.fps) + " would make more than " +
                       std::to_string(limits::kMaxFrames) + " frames (the limit)"};
    for (int64_t k = 0; static_cast<double>(k) * step <= duration + kSameKeyTicks; ++k)
      ticks.push_back(static_cast<double>(k) * step);
  } else {
    std::sort(keys.begin(), keys.end());
    for (double k : keys)
      if (ticks.empty() || k - ticks.back() > kSameKeyTicks) ticks.push_back(k);
    if (ticks.empty()) ticks.push_back(0.0);
  }
  if (Status st = limits::checkArray(
          path + ": " + std::to_string(ticks.size()) + " frames of " + std::to_string(nv) +
              " vertices",
          static_cast<double>(ticks.size()),
          static_cast<double>(nv * sizeof(Vec3) + raw.bones.size() * sizeof(Eigen::Affine3d)));
      !st)
    return st.error();
  out.asset.skin.bind_pose = out.asset.rest;

  for (double t : ticks) {
    std::map<const aiNode*, aiMatrix4x4> g;
    globalTransforms(scene->mRootNode, aiMatrix4x4(), channels, t, &g);
    AnimationFrame fr;
    fr.time = t / tps;
    for (const BoneDef& b : raw.bones)
      fr.bones.push_back(toEigen(g.at(b.node) * b.offset * b.mesh_bind_inverse));
    // The skin was built for these vertices and bones: this cannot fail.
    fr.vertices =
        skinPoints(out.asset.rest.vertices, out.asset.skin.vertex_weights, fr.bones).value();
    out.frames.push_back(std::move(fr));
  }
  return out;
}

}  // namespace sphereset
