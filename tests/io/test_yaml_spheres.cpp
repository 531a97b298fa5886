// cuRobo-style YAML sphere files: links read one by one in file order, flow and block style,
// spheres nested in a robot configuration, clear errors, round trips.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sphereset/sphere_io.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"
#include "util/utf8.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;

class YamlSpheres : public test::TempDirTest {};

void expectSphere(const Sphere& s, double x, double y, double z, double r) {
  EXPECT_EQ(s.center, Vec3(x, y, z));
  EXPECT_EQ(s.radius, r);
}

TEST_F(YamlSpheres, SeveralLinksAreNotMergedIntoOneSet) {
  const std::string p = test::dataPath("curobo_two_links.yml");
  auto r = readSpheres(p);
  ASSERT_FALSE(r.ok()) << "the spheres of two links were read as one set of " << r->size();
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(r.error().message.find(p), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("2 links (base_link, tool_link)"), std::string::npos)
      << r.error().message;
}

TEST_F(YamlSpheres, SingleLinkInFlowStyleAndNestedInARobotConfiguration) {
  auto flow = readSpheres(write("flow.yaml",
                                "collision_spheres:\n  arm: [{center: [1, 2, 3], radius: 0.5},\n"
                                "        {\"center\": [4, 5, 6], \"radius\": 1e-3}]\n"));
  ASSERT_TRUE(flow.ok()) << flow.error().message;
  ASSERT_EQ(flow->size(), 2u);
  expectSphere((*flow)[1], 4, 5, 6, 1e-3);
  auto one_line = readSpheres(write("line.yml",
                                    "collision_spheres: {arm: [{radius: 2, center: "
                                    "[1, 2, 3]}]}\n"));
  ASSERT_TRUE(one_line.ok()) << one_line.error().message;
  ASSERT_EQ(one_line->size(), 1u);
  expectSphere((*one_line)[0], 1, 2, 3, 2);
  // Other keys of a robot configuration hold "center" and "radius" too: only the spheres of
  // collision_spheres count.
  auto nested = readSpheres(
      write("robot.yml",
            "robot_cfg:\n  kinematics:\n    tool_center: [9, 9, 9]\n    radius_margin: 7\n"
            "    collision_spheres:\n      hand:\n        - center: [0.5, 0, 0]\n"
            "          radius: 0.25\n    extra_collision_spheres: {center: 4}\n"));
  ASSERT_TRUE(nested.ok()) << nested.error().message;
  ASSERT_EQ(nested->size(), 1u);
  expectSphere((*nested)[0], 0.5, 0, 0, 0.25);
}

TEST_F(YamlSpheres, LinksAreReadOneByOneInFileOrder) {
  auto links = readLinkSpheres(test::dataPath("curobo_two_links.yml"));
  ASSERT_TRUE(links.ok()) << links.error().message;
  ASSERT_EQ(links->size(), 2u);
  EXPECT_EQ((*links)[0].link, "base_link");
  ASSERT_EQ((*links)[0].spheres.size(), 2u);
  expectSphere((*links)[0].spheres[0], 0.0, 0.0, 0.25, 0.125);
  expectSphere((*links)[0].spheres[1], -0.5, 0.0, 0.25, 0.0625);
  EXPECT_EQ((*links)[1].link, "tool_link");
  ASSERT_EQ((*links)[1].spheres.size(), 1u);
  expectSphere((*links)[1].spheres[0], 1.0, -2.0, 1.5e-2, 0.75);

  // Nested under robot_cfg: kinematics:, flow style; the other keys are ignored.
  auto robot = readLinkSpheres(test::dataPath("curobo_robot_cfg.yml"));
  ASSERT_TRUE(robot.ok()) << robot.error().message;
  ASSERT_EQ(robot->size(), 2u);
  EXPECT_EQ((*robot)[0].link, "shoulder_link");
  ASSERT_EQ((*robot)[0].spheres.size(), 2u);
  expectSphere((*robot)[0].spheres[1], -0.25, 0.0, 0.125, 0.375);
  EXPECT_EQ((*robot)[1].link, "wrist_link");
  ASSERT_EQ((*robot)[1].spheres.size(), 1u);
  expectSphere((*robot)[1].spheres[0], 2.0, 3.0, -4.0, 0.25);

  // File order, not alphabetical; a link with an empty entry or list has no spheres.
  auto order = readLinkSpheres(
      write("order.yaml",
            "collision_spheres:\n  zeta: []\n  alpha:\n  mid:\n    - {center: [0, 0, 0], "
            "radius: 0}\n"));
  ASSERT_TRUE(order.ok()) << order.error().message;
  ASSERT_EQ(order->size(), 3u);
  EXPECT_EQ((*order)[0].link, "zeta");
  EXPECT_EQ((*order)[1].link, "alpha");
  EXPECT_EQ((*order)[2].link, "mid");
  EXPECT_TRUE((*order)[0].spheres.empty());
  EXPECT_TRUE((*order)[1].spheres.empty());
  EXPECT_EQ((*order)[2].spheres.size(), 1u);

  // Other formats hold one set: one link named after the file.
  auto txt = readLinkSpheres(write("gripper.txt", "1 2 3 4\n"));
  ASSERT_TRUE(txt.ok()) << txt.error().message;
  ASSERT_EQ(txt->size(), 1u);
  EXPECT_EQ((*txt)[0].link, "gripper");
  EXPECT_EQ((*txt)[0].spheres.size(), 1u);
}

TEST_F(YamlSpheres, BadFilesGiveOneLineErrorsNamingFileLinkAndSphere) {
  const std::string head = "collision_spheres:\n  arm:\n";
  struct Case {
    std::string text;
    ErrorCode code;
    std::string words;
  };
  const Case cases[] = {
      {"- 1\n- 2\n", ErrorCode::kInvalidData, "not a YAML mapping"},
      {"", ErrorCode::kInvalidData, "not a YAML mapping"},
      {"spheres: {}\n", ErrorCode::kInvalidData, "no collision_spheres"},
      {"robot_cfg:\n  kinematics:\n    collision_spheres: spheres/arm.yml\n",
       ErrorCode::kInvalidData,
       ":3: robot_cfg: kinematics: collision_spheres is 'spheres/arm.yml'"},
      {"collision_spheres: [1, 2]\n", ErrorCode::kInvalidData, "must map link names"},
      {head + "    7\n", ErrorCode::kInvalidData, ":3: link 'arm': expected a list of spheres"},
      {head + "    - 7\n", ErrorCode::kInvalidData, "link 'arm' sphere 0: expected {center"},
      {head + "    - {center: [1, 2, 3], radius: 1}\n    - {center: [1, 2, 3]}\n",
       ErrorCode::kInvalidData, ":4: link 'arm' sphere 1: radius is missing"},
      {head + "    - {radius: 1}\n", ErrorCode::kInvalidData, "sphere 0: center is missing"},
      {head + "    - {center: [1, 2], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: center must be a list of three numbers"},
      {head + "    - {center: [1, 2, 3, 4], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: center must be a list of three numbers"},
      {head + "    - {center: 5, radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: center must be a list"},
      {head + "    - {center: [1, x, 3], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: center is not numeric"},
      {head + "    - {center: [1, [2], 3], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: center is not numeric"},
      {head + "    - {center: [1, 2, 3], radius: \"0.5\"}\n", ErrorCode::kInvalidData,
       "sphere 0: radius is not a number"},
      {head + "    - {center: [1, 2, 3], radius: 1.5.2}\n", ErrorCode::kInvalidData,
       "sphere 0: radius is not a number"},
      {head + "    - {center: [1, 2, 3], radius: .nan}\n", ErrorCode::kInvalidData,
       "sphere 0: NaN or infinite value"},
      {head + "    - {center: [nan, 2, 3], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: NaN or infinite value"},
      {head + "    - {center: [1, 2, -.inf], radius: 1}\n", ErrorCode::kInvalidData,
       "sphere 0: NaN or infinite value"},
      {head + "    - {center: [1, 2, 3], radius: -0.5}\n", ErrorCode::kInvalidData,
       "sphere 0: negative radius"},
      {head + "    - {center: [1, 2, 3], radius: 1}\n  arm: []\n", ErrorCode::kInvalidData,
       "link 'arm' appears twice"},
      {head + "    - {center: [1, 2, 3], radius: 1\n", ErrorCode::kUnreadable, "invalid YAML"},
      {"collision_spheres:\n  arm: [\n", ErrorCode::kUnreadable, "invalid YAML"},
      {"a: b: c\n", ErrorCode::kUnreadable, ":1:5: invalid YAML"},
  };
  for (const Case& c : cases) {
    const std::string p = write("bad.yaml", c.text);
    auto r = readLinkSpheres(p);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().code, c.code) << c.text << " -> " << r.error().message;
    EXPECT_EQ(r.error().message.rfind(p, 0), 0u) << r.error().message;
    EXPECT_NE(r.error().message.find(c.words), std::string::npos)
        << c.text << " -> " << r.error().message;
    EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << r.error().message;
    // The single-set and tree readers give the same error.
    auto s = readSpheres(p);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, r.error().message);
    auto t = readSphereTree(p);
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().message, r.error().message);
  }
  // A link name with a line break stays on one line in the message.
  auto r = readLinkSpheres(write("nl.yaml", "collision_spheres:\n  \"a\\nb\": 3\n"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << r.error().message;
  // Several links are not one sphere set, for the tree reader either.
  auto t = readSphereTree(test::dataPath("curobo_robot_cfg.yml"));
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.error().message.find("2 links (shoulder_link, wrist_link)"), std::string::npos)
      << t.error().message;
}

using test::kRoundTripSet;

// An edited robot's spheres written back into the file they came from: the spheres replaced in
// place and layout, every other key as it was.
TEST_F(YamlSpheres, RewriteKeepsTheFileAroundTheSpheres) {
  const std::vector<LinkSpheres> edited = {{"base", {{Vec3(0.1, 0.2, 0.3), 0.25}}},
                                           {"arm", {{Vec3(-1, 0, 2.5), 0.5}, {Vec3(0, 0, 0), 1}}}};
  const auto readBack = [&](const std::string& file) {
    auto back = readLinkSpheres(file);
    EXPECT_TRUE(back.ok()) << back.error().message;
    if (!back.ok()) return;
    ASSERT_EQ(back->size(), 2u);
    for (size_t l = 0; l < 2; ++l) {
      EXPECT_EQ((*back)[l].link, edited[l].link);
      ASSERT_EQ((*back)[l].spheres.size(), edited[l].spheres.size());
      for (size_t k = 0; k < edited[l].spheres.size(); ++k) {
        EXPECT_EQ((*back)[l].spheres[k].center, edited[l].spheres[k].center);
        EXPECT_EQ((*back)[l].spheres[k].radius, edited[l].spheres[k].radius);
      }
    }
  };
  // cuRobo: the ignore list and the buffer stay.
  const std::string curobo = path("curobo.yml");
  std::ofstream(curobo) << "collision_spheres:\n  base:\n    - center: [0, 0, 0]\n      radius: 1\n"
                           "  arm:\n    - center: [0, 0, 1]\n      radius: 0.3\n"
                           "self_collision_ignore:\n  base: [arm]\n"
                           "self_collision_buffer:\n  base: 0.01\n";
  ASSERT_TRUE(rewriteLinkSpheres(curobo, path("curobo_out.yml"), edited).ok());
  readBack(path("curobo_out.yml"));
  const std::string text = test::readFile(path("curobo_out.yml"));
  EXPECT_NE(text.find("self_collision_ignore"), std::string::npos) << text;
  EXPECT_NE(text.find("self_collision_buffer"), std::string::npos) << text;
  EXPECT_NE(text.find("0.01"), std::string::npos) << text;
  // Lula: the list of one-link mappings stays a list, the description's other keys stay.
  const std::string lula = path("robot.lula.yml");
  std::ofstream(lula) << "api_version: 1.0\ncspace:\n  - joint1\n"
                         "collision_spheres:\n  - base:\n      - center: [0, 0, 0]\n"
                         "        radius: 1\n  - arm: []\n";
  ASSERT_TRUE(rewriteLinkSpheres(lula, path("robot_out.lula.yml"), edited).ok());
  readBack(path("robot_out.lula.yml"));
  const std::string lula_text = test::readFile(path("robot_out.lula.yml"));
  EXPECT_NE(lula_text.find("cspace"), std::string::npos) << lula_text;
  EXPECT_NE(lula_text.find("- base:"), std::string::npos) << lula_text;
  // Nested in a robot configuration: written back there.
  const std::string nested = path("nested.yml");
  std::ofstream(nested) << "robot_cfg:\n  kinematics:\n    urdf_path: robot.urdf\n"
                           "    collision_spheres:\n      base: []\n";
  ASSERT_TRUE(rewriteLinkSpheres(nested, path("nested_out.yml"), edited).ok());
  readBack(path("nested_out.yml"));
  EXPECT_NE(test::readFile(path("nested_out.yml")).find("urdf_path: robot.urdf"),
            std::string::npos);
  // A source that is no sphere file, or a target that is not YAML: refused, nothing written.
  std::ofstream(path("plain.yml")) << "a: 1\n";
  EXPECT_FALSE(rewriteLinkSpheres(path("plain.yml"), path("never.yml"), edited).ok());
  EXPECT_FALSE(rewriteLinkSpheres(curobo, path("never.txt"), edited).ok());
  EXPECT_FALSE(fs::exists(path("never.yml")));
  EXPECT_FALSE(fs::exists(path("never.txt")));
}

// The JSON report of `sphereset robot` reads as its links (the view takes it as a robot's
// spheres); a bad sphere in it is named.
TEST_F(YamlSpheres, ARobotsJsonReportReadsAsItsLinks) {
  const std::string report = write(
      "robot.json",
      R"({"robot": "r", "links": [{"link": "base", "spheres": [[0, 0, 0.5, 0.25]], "count": 1},
          {"link": "tool", "skipped": true},
          {"link": "arm", "spheres": [[1, 2, 3, 0.5], [0, 0, 0, 1]]}]})");
  auto links = readLinkSpheres(report);
  ASSERT_TRUE(links.ok()) << links.error().message;
  ASSERT_EQ(links->size(), 3u);
  EXPECT_EQ((*links)[0].link, "base");
  ASSERT_EQ((*links)[0].spheres.size(), 1u);
  expectSphere((*links)[0].spheres[0], 0, 0, 0.5, 0.25);
  EXPECT_TRUE((*links)[1].spheres.empty());
  ASSERT_EQ((*links)[2].spheres.size(), 2u);
  expectSphere((*links)[2].spheres[1], 0, 0, 0, 1);
  const std::string bad =
      write("bad.json", R"({"links": [{"link": "base", "spheres": [[0, 0, 0, -1]]}]})");
  auto refused = readLinkSpheres(bad);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(refused.error().message.find("'base') sphere 0"), std::string::npos)
      << refused.error().message;
  // A plain set in JSON is still one link named after the file.
  const std::string set = write("set.json", R"({"spheres": [{"center": [0, 0, 0], "radius": 1}]})");
  auto one = readLinkSpheres(set);
  ASSERT_TRUE(one.ok()) << one.error().message;
  ASSERT_EQ(one->size(), 1u);
  EXPECT_EQ((*one)[0].link, "set");
}

TEST_F(YamlSpheres, SingleLinkOutputIsUnchanged) {
  // The layout existing fits are compared against, byte for byte.
  SphereFileMeta meta;
  meta.name = "link_3";
  EXPECT_EQ(formatSpheres(SphereFormat::kYaml, kRoundTripSet, meta),
            "# sphereset: 3 spheres\n"
            "collision_spheres:\n"
            "  link_3:\n"
            "    - \"center\": [0.10000000000000001, -2.5, 3]\n"
            "      \"radius\": 0.75\n"
            "    - \"center\": [0.33333333333333331, 1.0000000000000001e-09, -7]\n"
            "      \"radius\": 0.001\n"
            "    - \"center\": [100, 200, 300]\n"
            "      \"radius\": 42\n");
  // A name that would not read back as itself is quoted.
  meta.name = "left arm: tip";
  const std::string p = write("q.yaml", formatSpheres(SphereFormat::kYaml, kRoundTripSet, meta));
  auto back = readLinkSpheres(p);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ((*back)[0].link, "left arm: tip");
}

TEST_F(YamlSpheres, SeveralLinksRoundTrip) {
  const std::vector<LinkSpheres> links = {
      {"panda_link0", kRoundTripSet},
      {"panda_hand", {kRoundTripSet[1]}},
      {"empty", {}},
      {"true", {kRoundTripSet[2]}},
      {"1.5", {kRoundTripSet[0]}},
      {"a \"quoted\"\\ name\t#1", {kRoundTripSet[0], kRoundTripSet[2]}}};
  const std::string p = path("robot.yaml");
  SphereFileMeta meta;
  ASSERT_TRUE(writeLinkSpheres(p, links, meta).ok());
  auto back = readLinkSpheres(p);
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->size(), links.size());
  for (size_t l = 0; l < links.size(); ++l) {
    EXPECT_EQ((*back)[l].link, links[l].link);
    ASSERT_EQ((*back)[l].spheres.size(), links[l].spheres.size()) << links[l].link;
    for (size_t i = 0; i < links[l].spheres.size(); ++i) {
      EXPECT_EQ((*back)[l].spheres[i].center, links[l].spheres[i].center);
      EXPECT_EQ((*back)[l].spheres[i].radius, links[l].spheres[i].radius);
    }
  }
  const std::string text = formatLinkSpheres(links, meta);
  EXPECT_EQ(text.rfind("# sphereset: 8 spheres in 6 links\ncollision_spheres:\n  panda_link0:\n"
                       "    - \"center\": [0.10000000000000001, -2.5, 3]\n",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("\n  empty: []\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  \"true\":\n"), std::string::npos) << text;

  // One link written by either writer reads back the same.
  ASSERT_TRUE(writeSpheres(path("one.yaml"), kRoundTripSet).ok());
  auto one = readLinkSpheres(path("one.yaml"));
  ASSERT_TRUE(one.ok()) << one.error().message;
  ASSERT_EQ(one->size(), 1u);
  EXPECT_EQ((*one)[0].link, "object");
  EXPECT_EQ((*one)[0].spheres.size(), kRoundTripSet.size());
  // An empty set written by the single-link writer is a link without spheres.
  ASSERT_TRUE(writeSpheres(path("none.yaml"), {}).ok());
  auto none = readSpheres(path("none.yaml"));
  ASSERT_TRUE(none.ok()) << none.error().message;
  EXPECT_TRUE(none->empty());
  ASSERT_TRUE(writeLinkSpheres(path("no_links.yaml"), {}).ok());
  auto no_links = readLinkSpheres(path("no_links.yaml"));
  ASSERT_TRUE(no_links.ok()) << no_links.error().message;
  EXPECT_TRUE(no_links->empty());
}

TEST_F(YamlSpheres, WritingSeveralLinksChecksThem) {
  auto expectRefused = [&](const std::string& p, const std::vector<LinkSpheres>& links,
                           ErrorCode code, const std::string& words) {
    Status st = writeLinkSpheres(p, links);
    ASSERT_FALSE(st.ok()) << words;
    EXPECT_EQ(st.error().code, code) << st.error().message;
    EXPECT_NE(st.error().message.find(words), std::string::npos) << st.error().message;
    EXPECT_FALSE(fs::exists(p));
  };
  expectRefused(path("a.txt"), {{"a", kRoundTripSet}}, ErrorCode::kInvalidArgument,
                "written as YAML");
  expectRefused(path("a.yaml"), {{"a", kRoundTripSet}, {"a", {}}}, ErrorCode::kInvalidArgument,
                "link 'a' appears twice");
  expectRefused(path("a.yaml"), {{"", kRoundTripSet}}, ErrorCode::kInvalidArgument,
                "link 0 has no name");
  std::vector<Sphere> bad = kRoundTripSet;
  bad[2].radius = -1.0;
  expectRefused(path("a.yaml"), {{"a", kRoundTripSet}, {"b", bad}}, ErrorCode::kInvalidData,
                "link 'b' sphere 2: negative radius");
}

TEST_F(YamlSpheres, LongAndUnusualLinkNamesRoundTrip) {
  // Found by fuzzing: a link name longer than YAML's 1024-character limit on implicit keys was
  // written as one, and the file did not read back. Such keys are written in the explicit
  // "? key" form; other bytes (controls, line separators) read back as they were. A YAML file is
  // UTF-8: bytes that are not (a name from a file name) are written as U+FFFD.
  const std::vector<LinkSpheres> links = {{std::string(2000, 'k'), {kRoundTripSet[0]}},
                                          {std::string(600, '\x1f'), {}},
                                          {"\xff\xfe not UTF-8", {kRoundTripSet[1]}},
                                          {"a\xc2\x85"
                                           "b\xe2\x80\xa8"
                                           "c",
                                           {}},
                                          {std::string("nul\0byte", 8), {kRoundTripSet[2]}}};
  for (const LinkSpheres& l : links) {
    SCOPED_TRACE(l.link.size());
    const std::string p = path("long.yaml");
    ASSERT_TRUE(writeLinkSpheres(p, {l, {"next", {kRoundTripSet[2]}}}).ok());
    auto back = readLinkSpheres(p);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->size(), 2u);
    const std::string expected = detail::validUtf8(l.link);
    EXPECT_EQ((*back)[0].link, expected);
    EXPECT_EQ((*back)[0].spheres.size(), l.spheres.size());
    EXPECT_EQ((*back)[1].link, "next");
    // The same through the single-link writer.
    SphereFileMeta meta;
    meta.name = l.link;
    ASSERT_TRUE(writeSpheres(p, kRoundTripSet, meta).ok());
    auto one = readLinkSpheres(p);
    ASSERT_TRUE(one.ok()) << one.error().message;
    ASSERT_EQ(one->size(), 1u);
    EXPECT_EQ((*one)[0].link, expected);
    EXPECT_EQ((*one)[0].spheres.size(), kRoundTripSet.size());
  }
}

}  // namespace
}  // namespace sphereset
