// A robot's links in the view take the solids the robot command fits them to: link_solid for
// all, link_solid_for for one (robot_fit.hpp), and a name the robot lacks is refused.
#include <gtest/gtest.h>

#include <string>

#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

TEST_F(ViewTest, ARobotsLinksTakeTheirOwnSolids) {
  const std::string file = robotSpheres();
  ViewLoadOptions o = robotOptions();
  // The envelope for all but the two links drawn, which take their walls: no wrapping needed.
  o.link_solid = LinkSolid::kEnvelope;
  o.link_solid_for = {{"link1", LinkSolid::kWalls}, {"link2", LinkSolid::kWalls}};
  auto loaded = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ASSERT_EQ(loaded->solids.size(), 2u);
  o.link_solid_for["link2"] = LinkSolid::kEnvelope;
  auto envelope = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_FALSE(envelope.ok());
  EXPECT_NE(envelope.error().message.find("link 'link2'"), std::string::npos)
      << envelope.error().message;
  o.link_solid_for = {{"elbow", LinkSolid::kWalls}};
  auto bad = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.error().message.find("link_solid_for names 'elbow', not a link of"),
            std::string::npos)
      << bad.error().message;
}

}  // namespace
}  // namespace sphereset::test
