// Private: the JSON pieces of the view's API (docs/view.md), shared by the scene's text, the
// answers of the edits and the static page.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/view.hpp"

namespace sphereset::view_json {

nlohmann::json spheres(const std::vector<Sphere>& set);  // [[x, y, z, r], ...]
nlohmann::json certificate(const ViewCertificate& c);    // CERTIFICATE
nlohmann::json solid(const ViewSolid& s);                // one entry of "solids"
nlohmann::json joints(const ViewScene& scene);           // the movable joints
nlohmann::json poses(const ViewScene& scene);            // 16 numbers per solid, row-major
nlohmann::json collisions(const ViewScene& scene);       // robots: allowed and contact pairs
nlohmann::json save(const ViewScene& scene);             // "save": path, format, "as"
nlohmann::json scene(const ViewScene& scene);            // GET /api/scene
// Static pages: the robot's joint tree (what linkPoses needs), and a tree's every level with its
// certificate (certified here: a level not shown has none yet).
nlohmann::json kinematics(const Robot& robot);
nlohmann::json levelSets(const ViewSolid& s);

}  // namespace sphereset::view_json
