// Sphere files: sphere sets and sphere trees in text, JSON, Bradshaw's .sph and cuRobo YAML.
// Reading a file needs nothing of the fit.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

enum class SphereFormat {
  kText,  // "x y z r" per line, '#' starts a comment
  kJson,  // {"spheres": [{"center": [x, y, z], "radius": r}, ...], ...metadata}
  kSph,   // Bradshaw's sphere-tree layout; a flat set is written as root + one level
  kYaml,  // cuRobo's "collision_spheres:" mapping of link names to lists of spheres
};

// Format from a file name's extension (.txt/.xyzr, .json, .sph, .yaml/.yml); kInvalidArgument
// for anything else.
Expected<SphereFormat> sphereFormatFromPath(const std::string& path);
// A format's name, as every door (options, Python, the page) spells it: "txt", "json", "sph",
// "yaml"; and the format of one of those names exactly (kInvalidArgument "format 'X': expected
// txt, json, sph or yaml" otherwise: the Python module took "yml" and "text" where the command
// refused them).
const char* sphereFormatName(SphereFormat format);
Expected<SphereFormat> sphereFormatFromName(const std::string& name);

struct SphereFileMeta {
  std::string name = "object";  // link name for YAML output
  std::string source_mesh;      // recorded in JSON output
  std::string generator = "sphereset";
};

// Reads a sphere set in the format given by the extension. For .sph files the deepest level
// with spheres of positive radius is returned. A YAML file must hold one link (see
// readLinkSpheres for several). Errors: kUnreadable, kInvalidData (NaN, negative radius,
// malformed line, several links; the message names the line or the links).
Expected<std::vector<Sphere>> readSpheres(const std::string& path);

// The spheres of one link of a robot.
struct LinkSpheres {
  std::string link;
  std::vector<Sphere> spheres;
};

// Reads every link of a YAML file in file order, as cuRobo writes them: a "collision_spheres:"
// mapping of link names to lists of spheres {center: [x, y, z], radius: r} (flow or block
// style) at the top level, or nested as robot_cfg: kinematics: collision_spheres: (or
// kinematics: collision_spheres:), or Lula's list of one-link mappings
// (collision_spheres: [{link: [spheres]}, ...], robot_collision.hpp). A link
// with an empty entry has no spheres. Any other format holds one set, returned as one link
// named after the file's stem, but for the JSON report of `sphereset robot -o ROBOT.json`
// ({"links": [{"link": NAME, "spheres": [[x, y, z, r], ...]}, ...]}), read as its links.
// Errors: kUnreadable (not YAML), kInvalidData (no
// collision_spheres, a link that is not a list, a sphere without center or radius, a value
// that is not a number, NaN, negative radius; the message names the file, line, link and
// sphere index).
Expected<std::vector<LinkSpheres>> readLinkSpheres(const std::string& path);

// Writes atomically: to a temporary file beside the target, then renamed over it, so a failed
// write never leaves a partial file.
Status writeSpheres(const std::string& path, const std::vector<Sphere>& spheres,
                    const SphereFileMeta& meta = {});

// The same, into a string (tests and embedding).
std::string formatSpheres(SphereFormat format, const std::vector<Sphere>& spheres,
                          const SphereFileMeta& meta = {});

// The spheres of several links in one YAML file (.yaml/.yml, else kInvalidArgument), in the
// layout writeSpheres uses for one link; a link without spheres is written as "[]". Link names
// must be non-empty and distinct. Written atomically.
Status writeLinkSpheres(const std::string& path, const std::vector<LinkSpheres>& links,
                        const SphereFileMeta& meta = {});
std::string formatLinkSpheres(const std::vector<LinkSpheres>& links,
                              const SphereFileMeta& meta = {});

// The YAML file `source` (cuRobo's or Lula's, as readLinkSpheres reads it) written to `path`
// with its collision spheres replaced by `links`, in the same place and layout, every other key
// kept (cuRobo's self_collision_ignore and buffer, Lula's robot description); comments are not
// kept. How an edited set goes back into the file it came from. Errors: readLinkSpheres' for the
// source, writeLinkSpheres' for the links and the path. Written atomically.
Status rewriteLinkSpheres(const std::string& source, const std::string& path,
                          const std::vector<LinkSpheres>& links);

// Writes any text atomically, as the sphere files are written (e.g. a command's JSON report).
Status writeTextFile(const std::string& path, const std::string& text);

// Before a long computation, whether `output` can be written when it ends: kInvalidArgument when
// it is one of `inputs` (the same file once links and relative paths are resolved: a run that
// overwrote its input would lose it, and a second run would fit spheres to spheres) or names a
// folder; kWriteFailed when its folder does not exist or does not accept new files (tried by
// creating and removing a temporary file there). Nothing is left behind.
Status checkOutputPath(const std::string& output, const std::vector<std::string>& inputs);
// The same for an output folder that a command fills (created when missing, with its parents):
// not an input, not a file, and writable where it exists or would be created.
Status checkOutputFolder(const std::string& folder, const std::vector<std::string>& inputs);

// Pairs of links to leave out of self-collision checking, as cuRobo lists them: links joined
// by a joint (adjacent), and the others to ignore (overlapping): links whose sphere sets overlap
// at one pose (selfCollisionPairs), or every other pair the joint-space sampling disabled
// (ignoredPairs, robot_collision.hpp). Each pair
// {a, b} has a before b in the robot's link order; the lists are sorted by that order and hold
// no duplicates. A pair both adjacent and overlapping is in both lists.
struct SelfCollisionPairs {
  std::vector<std::array<std::string, 2>> adjacent;
  std::vector<std::array<std::string, 2>> overlapping;
};

// A robot's spheres for cuRobo: the collision_spheres mapping of writeLinkSpheres, followed,
// when `pairs` is given, by the self_collision_ignore mapping (each link -> the list of links to
// ignore with it; every pair of pairs->adjacent and pairs->overlapping once, under the link that
// comes first in `links`, links not in `links` after them in the order they appear in the pairs)
// and the self_collision_buffer mapping (0.0 for every link with spheres). readLinkSpheres reads
// such a file (the two extra mappings are ignored). Same checks as writeLinkSpheres; written
// atomically.
Status writeRobotSpheres(const std::string& path, const std::vector<LinkSpheres>& links,
                         const SelfCollisionPairs* pairs, const SphereFileMeta& meta = {});
std::string formatRobotSpheres(const std::vector<LinkSpheres>& links,
                               const SelfCollisionPairs* pairs, const SphereFileMeta& meta = {});

// Tree files: Bradshaw's .sph ("levels branching" then one "x y z r error" line per slot) or
// JSON with explicit parent/child links per node. Writes are atomic.
Status writeSphereTree(const std::string& path, const SphereTree& tree,
                       const SphereFileMeta& meta = {});
std::string formatSphereTree(SphereFormat format, const SphereTree& tree,
                             const SphereFileMeta& meta = {});
// Reads a .sph tree, or a JSON file written by writeSphereTree. A plain sphere set (any format
// readSpheres accepts) is returned as a one-level tree holding just those spheres.
Expected<SphereTree> readSphereTree(const std::string& path);

}  // namespace sphereset
