// Transfer-function files (issue 35): Voxray's JSON and 3D Slicer's volume property (.vp),
// written here from the format's description (Slicer's developer guide, "Format of Volume
// Property (.vp) file"), read field by field, written back exactly, and refused with the
// field named when wrong.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// Every field: interpolation, shade, diffuse, ambient, specular, power, the scalar opacity
// (4 points), a gradient opacity that does something (3 points) and the colour (4 points).
const char* kSlicerBone =
    "1\n"
    "1\n"
    "0.9\n"
    "0.1\n"
    "0.2\n"
    "10\n"
    "8 -1000 0 152.19 0 278.93 0.190476 3071 0.705882\n"
    "6 0 0 20 0.5 255 1\n"
    "16 -1000 0.3 0.3 1 152.19 1 0.5 0.25 278.93 1 1 0.9 3071 0.827 0.658 1\n";

std::string refusal(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

std::string slicerRefusal(const std::string& text) {
  return refusal([&] { parseSlicerVolumeProperty(text, "b.vp"); });
}

std::string jsonRefusal(const std::string& text) {
  return refusal([&] { parseVolumePropertyJson(text, "b.json"); });
}

VolumeProperty awkward(TfCurve curve) {
  VolumeProperty vp;
  vp.name = "Vessels · test";
  vp.curve = curve;
  vp.unitDistanceMm = 0.7;
  vp.color = {{-86.9767, {0.1, 1.0 / 3.0, 0.0}},
              {45.3791, {1.0, 0.0, 0.2}},
              {45.3791, {1.0, 0.894893, 0.894893}},
              {3071.0, {0.827451, 0.658824, 1.0}}};
  vp.opacity = {{-3024.0, 0.0}, {139.919, 0.589286}, {347.907, 0.607143}, {3071.0, 1.0 / 7.0}};
  vp.gradientOpacity = {{0.0, 0.25}, {100.0, 1.0}};
  vp.shade = false;
  vp.nearest = true;
  vp.ambient = 0.12345678901234;
  vp.diffuse = 0.8;
  vp.specular = 0.3;
  vp.specularPower = 17.5;
  return vp;
}

}  // namespace

TEST(VolumePropertyFiles, ASlicerFileGivesEveryField) {
  const VolumeProperty vp = parseSlicerVolumeProperty(kSlicerBone, "bone.vp");
  EXPECT_FALSE(vp.nearest);
  EXPECT_TRUE(vp.shade);
  EXPECT_EQ(vp.diffuse, 0.9);
  EXPECT_EQ(vp.ambient, 0.1);
  EXPECT_EQ(vp.specular, 0.2);
  EXPECT_EQ(vp.specularPower, 10.0);
  ASSERT_EQ(vp.opacity.size(), 4u);
  EXPECT_EQ(vp.opacity[2], (OpacityNode{278.93, 0.190476}));
  ASSERT_EQ(vp.color.size(), 4u);
  EXPECT_EQ(vp.color[1], (ColorNode{152.19, {1.0, 0.5, 0.25}}));
  ASSERT_EQ(vp.gradientOpacity.size(), 3u);
  EXPECT_TRUE(hasGradientOpacity(vp));
  EXPECT_DOUBLE_EQ(gradientOpacityAt(vp, 10.0), 0.25);
  EXPECT_EQ(vp.curve, TfCurve::Linear);  // Slicer's functions are straight lines
  EXPECT_EQ(vp.unitDistanceMm, 0.0);     // .vp has none: per smallest voxel spacing
  // Opacity at 200 HU: a third of the way from 0 at 152.19 to 0.190476 at 278.93.
  EXPECT_NEAR(opacityAt(vp, 200.0), 0.190476 * (200.0 - 152.19) / (278.93 - 152.19), 1e-12);
}

TEST(VolumePropertyFiles, SlicersConstantGradientOpacityIsOff) {
  std::string text = kSlicerBone;
  text.replace(text.find("6 0 0 20 0.5 255 1"), 18, "4 0 1 255 1");
  const VolumeProperty vp = parseSlicerVolumeProperty(text, "bone.vp");
  EXPECT_TRUE(vp.gradientOpacity.empty());
  EXPECT_FALSE(hasGradientOpacity(vp));
}

TEST(VolumePropertyFiles, VoxrayToSlicerAndBackIsExact) {
  VolumeProperty vp = awkward(TfCurve::Linear);
  vp.unitDistanceMm = 0.0;  // .vp has no unit distance, curve or name
  vp.name.clear();
  EXPECT_EQ(parseSlicerVolumeProperty(toSlicerVolumeProperty(vp), "x.vp"), vp);
  // And Slicer's own text is written back number for number.
  const VolumeProperty bone = parseSlicerVolumeProperty(kSlicerBone, "bone.vp");
  EXPECT_EQ(toSlicerVolumeProperty(bone), kSlicerBone);
}

TEST(VolumePropertyFiles, ASmoothCurveGoesToSlicerAsItsTable) {
  VolumeProperty vp = awkward(TfCurve::Smooth);
  const VolumeProperty back = parseSlicerVolumeProperty(toSlicerVolumeProperty(vp), "x.vp");
  EXPECT_EQ(back.curve, TfCurve::Linear);
  EXPECT_GT(back.opacity.size(), vp.opacity.size());
  double worst = 0.0;
  for (double hu = -3100.0; hu <= 3100.0; hu += 0.5) {
    worst = std::max(worst, std::abs(opacityAt(back, hu) - opacityAt(vp, hu)));
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(colorAt(back, hu)[k] - colorAt(vp, hu)[k]));
  }
  EXPECT_LE(worst, 1.0 / 1024.0);
}

TEST(VolumePropertyFiles, VoxrayJsonRoundTripIsExact) {
  for (TfCurve curve : {TfCurve::Linear, TfCurve::Smooth}) {
    const VolumeProperty vp = awkward(curve);
    EXPECT_EQ(parseVolumePropertyJson(toVolumePropertyJson(vp), "x.json"), vp);
  }
}

TEST(VolumePropertyFiles, FilesByExtensionAndNeverOverAnother) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("voxray-tf-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const VolumeProperty vp = awkward(TfCurve::Smooth);
  writeVolumePropertyFile(vp, (dir / "v.json").string());
  EXPECT_EQ(readVolumePropertyFile((dir / "v.json").string()), vp);
  VolumeProperty linear = awkward(TfCurve::Linear);
  linear.unitDistanceMm = 0.0;
  writeVolumePropertyFile(linear, (dir / "Vessels.vp").string());
  VolumeProperty read = readVolumePropertyFile((dir / "Vessels.vp").string());
  EXPECT_EQ(read.name, "Vessels");  // a .vp is named by its file
  read.name = linear.name;
  EXPECT_EQ(read, linear);
  EXPECT_EQ(refusal([&] { readVolumePropertyFile((dir / "v.txt").string()); }),
            (dir / "v.txt").string() +
                ": a transfer function file ends in .json (Voxray) or .vp (3D Slicer)");
  EXPECT_EQ(
      refusal([&] { readVolumePropertyFile((dir / "missing.vp").string()); }),
      (dir / "missing.vp").string() + ": cannot open the transfer function file; check the path");
  fs::remove_all(dir);
}

TEST(VolumePropertyFiles, ABadSlicerFileNamesTheField) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string t = kSlicerBone;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  EXPECT_EQ(slicerRefusal(with("8 -1000 0 152.19", "7 -1000 0 152.19")),
            "b.vp: the scalar opacity function count is 7; it counts the numbers that follow, 2 "
            "per point");
  EXPECT_EQ(slicerRefusal(with("278.93 0.190476", "100 0.190476")),
            "b.vp: opacity point 3 (at 100) comes after one at 152.19; points must be sorted by "
            "position");
  EXPECT_EQ(slicerRefusal(with("278.93 0.190476", "278.93 1.5")),
            "b.vp: opacity point 3 has 1.5; it must lie in 0 ... 1");
  EXPECT_EQ(slicerRefusal(with("278.93 0.190476", "278.93 nan")),
            "b.vp: opacity point 3 has nan; it must lie in 0 ... 1");
  EXPECT_EQ(slicerRefusal(with("0.9\n", "O.9\n")),
            "b.vp: the diffuse reflection (third number) is 'O.9', not a number");
  EXPECT_EQ(slicerRefusal(with("16 -1000", "2000000 -1000")),
            "b.vp: the colour function has 500000 points; at most 4096 are read");
  EXPECT_EQ(slicerRefusal("1\n1\n0.9\n0.1\n0.2\n10\n8 -1000 0 152.19 0\n"),
            "b.vp: the file ends before the scalar opacity function point 3; a Slicer volume "
            "property has six numbers, then the scalar opacity, gradient opacity and colour "
            "functions");
  EXPECT_EQ(slicerRefusal(with(
                "16 -1000 0.3 0.3 1 152.19 1 0.5 0.25 278.93 1 1 0.9 3071 0.827 0.658 1", "0")),
            "b.vp: colour has no points; give at least one");
  EXPECT_EQ(slicerRefusal(with("1\n1\n0.9", "3\n1\n0.9")),
            "b.vp: the interpolation type is 3; it must be 0 (nearest), 1 (linear) or 2 (cubic, "
            "read as linear)");
}

TEST(VolumePropertyFiles, ABadJsonFileNamesTheField) {
  const std::string head = R"({"format": "voxray-transfer-function", "version": 1, )";
  EXPECT_EQ(jsonRefusal(R"({"name": "x"})"),
            "b.json: not a Voxray transfer function (its \"format\" must be "
            "\"voxray-transfer-function\")");
  EXPECT_EQ(jsonRefusal(R"({"format": "voxray-transfer-function", "version": 2})"),
            "b.json: version 2 is not one this Voxray reads (it reads version 1); a newer Voxray "
            "wrote it");
  EXPECT_EQ(jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[0, 0.5, 1]]})"),
            "b.json: opacity point 1 must be a list of 2 numbers");
  EXPECT_EQ(jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[0, "a"]]})"),
            "b.json: opacity point 1 must be a number");
  EXPECT_EQ(jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[10, 0], [0, 1]]})"),
            "b.json: opacity point 2 (at 0) comes after one at 10; points must be sorted by "
            "position");
  // Found by the transfer-function fuzzer: a number where text belongs threw nlohmann's
  // type error past every caller (the editor's Load would have ended the workstation).
  EXPECT_EQ(jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[0, 1]], "curve": 2})"),
            "b.json: curve must be text");
  EXPECT_EQ(
      jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[0, 1]], "interpolation": [1]})"),
      "b.json: interpolation must be text");
  EXPECT_EQ(jsonRefusal(R"({"format": 7})"),
            "b.json: not a Voxray transfer function (its \"format\" must be "
            "\"voxray-transfer-function\")");
  EXPECT_EQ(
      jsonRefusal(head + R"("color": [[0, 1, 1, 1]], "opacity": [[0, 1]], "curve": "cubic"})"),
      "b.json: curve is 'cubic'; it must be linear or smooth");
  std::string many = head + R"("color": [[0, 1, 1, 1]], "opacity": [)";
  for (int i = 0; i < 1000000; ++i) many += (i ? ",[" : "[") + std::to_string(i) + ",0]";
  many += "]}";
  EXPECT_EQ(jsonRefusal(many), "b.json: opacity has 1000000 points; at most 4096 are read");
  EXPECT_EQ(jsonRefusal("{\"format\": "), jsonRefusal("{\"format\": "));  // stable
  EXPECT_NE(jsonRefusal("{\"format\": ").find("b.json: not valid JSON"), std::string::npos);
}

}  // namespace voxray

namespace voxray {

namespace {

// A preset list in 3D Slicer's form (its VolumeRendering module's presets.xml): written here
// from the format, two presets, one with a gradient opacity.
const char* kPresetList = R"(<?xml version="1.0" encoding="UTF-8"?>
<PresetList>
  <VolumeProperty name="Bone-Test" interpolation="1" shade="1" ambient="0.1" diffuse="0.9"
    specular="0.2" specularPower="10" gradientOpacity="4 0 1 255 1"
    scalarOpacity="8 -1000 0 152.19 0 278.93 0.190476 3071 0.705882"
    colorTransfer="16 -1000 0.3 0.3 1 152.19 1 0.5 0.25 278.93 1 1 0.9 3071 0.827 0.658 1"
    effectiveRange="152.19 3071" selectable="true"/>
  <VolumeProperty name="Edges-Test" interpolation="0" shade="0" ambient="0.3" diffuse="0.6"
    specular="0" specularPower="1" gradientOpacity="6 0 0 20 0.5 255 1"
    scalarOpacity="4 0 0 500 1" colorTransfer="8 0 0 0 0 500 1 1 1"/>
</PresetList>
)";

}  // namespace

TEST(VolumePropertyFiles, ASlicerPresetListGivesEveryPreset) {
  const std::vector<VolumeProperty> presets = parseSlicerPresets(kPresetList, "presets.xml");
  ASSERT_EQ(presets.size(), 2u);
  EXPECT_EQ(presets[0].name, "Bone-Test");
  // The same fields as the .vp file of the same numbers, but for the gradient opacity.
  VolumeProperty fromVp = parseSlicerVolumeProperty(kSlicerBone, "bone.vp");
  fromVp.name = "Bone-Test";
  fromVp.gradientOpacity.clear();  // the list's Bone-Test has Slicer's constant 1 (off)
  EXPECT_EQ(presets[0], fromVp);
  const VolumeProperty& edges = findProperty(presets, "edges-test", "presets.xml");
  EXPECT_TRUE(edges.nearest);
  EXPECT_FALSE(edges.shade);
  EXPECT_EQ(edges.ambient, 0.3);
  EXPECT_TRUE(hasGradientOpacity(edges));
  EXPECT_EQ(refusal([&] { findProperty(presets, "CT-AAA", "presets.xml"); }),
            "presets.xml: no preset named 'CT-AAA'; it has Bone-Test, Edges-Test");
}

TEST(VolumePropertyFiles, ABadPresetListNamesThePresetAndTheAttribute) {
  auto refused = [](std::string xml) { return refusal([&] { parseSlicerPresets(xml, "p.xml"); }); };
  std::string noShade = kPresetList;
  noShade.replace(noShade.find("shade=\"1\" "), 10, "");
  EXPECT_EQ(refused(noShade), "p.xml, preset 'Bone-Test': the attribute 'shade' is missing");
  std::string badCount = kPresetList;
  badCount.replace(badCount.find("scalarOpacity=\"4"), 16, "scalarOpacity=\"5");
  EXPECT_EQ(refused(badCount),
            "p.xml, preset 'Edges-Test': the scalar opacity function count is 5; it counts the "
            "numbers that follow, 2 per point");
  EXPECT_EQ(refused("<PresetList></PresetList>"),
            "p.xml: no <VolumeProperty> presets in it; 3D Slicer's list is "
            "<PresetList><VolumeProperty name=... /></PresetList>");
  EXPECT_EQ(refused("<PresetList><VolumeProperty").rfind("p.xml: not valid XML (", 0), 0u);
}

}  // namespace voxray
