#include <gtest/gtest.h>

#include "voxray/engine/render_params.h"
#include "voxray/engine/step.h"
#include "voxray/io/error.h"

namespace voxray {

TEST(RenderParams, TextRoundTripKeepsEveryDeclaredValue) {
  RenderParams p;
  fromText(p,
           "size=640x480\nmode=dvr\niso=100,900\ngradient=zucker-hummel\ninterp=nearest\n"
           "step=0.25\nrefine=6\nazimuth=30\nelevation=-15\nzoom=2\nclip=0.1,0.9,0,1,0.25,0.75\n"
           "light=100,-200,300\ntf=-1000:0:0:0:0,100:0:0:0:0,100:1:0.5:0:0.75\n");
  EXPECT_EQ(p.width, 640);
  EXPECT_EQ(p.mode, Mode::Dvr);
  EXPECT_EQ(p.gradient, Gradient::ZuckerHummel);
  EXPECT_DOUBLE_EQ(p.clip.lo.z, 0.25);
  EXPECT_FALSE(p.light.followCamera);
  RenderParams q;
  fromText(q, toText(p));
  EXPECT_EQ(toText(q), toText(p));
  EXPECT_DOUBLE_EQ(q.light.position.y, -200.0);
  ASSERT_EQ(q.transferFunction.size(), 3u);
  EXPECT_EQ(q.transferFunction[2].rgba, glm::dvec4(1.0, 0.5, 0.0, 0.75));
  EXPECT_DOUBLE_EQ(q.transferFunction[2].hu, 100.0);
}

TEST(RenderParams, BadValuesNameTheFlag) {
  RenderParams p;
  auto message = [&](const std::string& line) {
    try {
      fromText(p, line);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("mode=volume"), "--mode: 'volume' is not one of iso, dvr, mip");
  EXPECT_EQ(message("size=0x10"), "--size: 0x10 is outside 1x1 ... 16384x16384");
  EXPECT_NE(message("clip=0.5,0.4,0,1,0,1").find("lo <= hi"), std::string::npos);
  EXPECT_NE(message("zoom=0").find("greater than 0"), std::string::npos);
  EXPECT_NE(message("iso=abc").find("'abc' is not a number"), std::string::npos);
  EXPECT_NE(message("colour=red").find("unknown key 'colour'"), std::string::npos);
  EXPECT_EQ(message("tf=100:1:0:0"),
            "--tf: each point is HU:R:G:B:A with a finite HU, got '100:1:0:0'");
  EXPECT_EQ(message("tf=100:1:0:0:1.5"),
            "--tf: colour and opacity must lie in 0 ... 1, got '100:1:0:0:1.5'");
}

TEST(RenderParams, DefaultStepIsHalfTheSmallestSpacing) {
  RenderParams p;
  EXPECT_DOUBLE_EQ(effectiveStepMm(p, 0.8), 0.4);
  p.stepMm = 2.0;
  EXPECT_DOUBLE_EQ(effectiveStepMm(p, 0.8), 2.0);
}

}  // namespace voxray
