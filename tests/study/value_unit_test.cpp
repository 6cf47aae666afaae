// Issue 41 item 8 (and item 2's units): raw CThead opened with the HU rescale (1, -1024)
// opened at W3272/L612, its value range, as though its values were not HU; and the panel and
// the readouts said "HU" for an MR or a raw volume nobody had rescaled. A rescale the user
// gives makes raw values HU (a CT window, the CT look); without one they are "value".
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "slice_image.h"
#include "study_state.h"
#include "value_look.h"
#include "voxray/io/phantom.h"
#include "voxray/io/raw_import.h"

using namespace voxray;
namespace fs = std::filesystem;

namespace {

// A 4x4x2 raw CT in the Stanford way: raw CT numbers 0 (air) ... 3272, not HU-shifted.
class RawCtFile : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ =
        fs::temp_directory_path() / ("voxray_value_unit_" + std::to_string(::getpid()) + ".raw");
    std::vector<int16_t> samples(32, 0);
    samples[5] = 1024;  // water
    samples[31] = 3272;
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(samples.data()), std::streamsize(64));
  }
  void TearDown() override { fs::remove(path_); }
  Volume load(double slope, double intercept) const {
    RawLayout l;
    l.dims = {4, 4, 2};
    l.slope = slope;
    l.intercept = intercept;
    return importRaw(path_.string(), l);
  }
  fs::path path_;
};

TEST_F(RawCtFile, WithTheHuRescaleItOpensAtTheCtWindow) {
  const Volume v = load(1.0, -1024.0);
  EXPECT_EQ(v.unit, "HU");
  EXPECT_TRUE(valuesAreHu(v));
  const InitialWindow w = initialWindow(v);
  EXPECT_DOUBLE_EQ(w.wl.width, 400.0);  // not 3272 (the value range)
  EXPECT_DOUBLE_EQ(w.wl.level, 40.0);   // not 612
  EXPECT_EQ(w.source, "CT default (no window given)");
  EXPECT_EQ(valueUnit(v), "HU");
  EXPECT_EQ(probeAt(v, glm::dvec3(1, 1, 0), Interp::Nearest).unit, "HU");

  // Opened as a study: the CT look (the user's HU preferences), not one from the histogram.
  AppModels m;
  m.render.update(kAppearance, [](RenderParams& p) { p.isoLo = 400.0; });
  openStudy(m, std::make_shared<const Volume>(v), "CThead");
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 400.0);
  EXPECT_DOUBLE_EQ(m.render.params().isoLo, 400.0);
  EXPECT_FALSE(m.huLook.has_value());
}

TEST_F(RawCtFile, WithoutARescaleItsValuesAreNotCalledHu) {
  const Volume v = load(1.0, 0.0);
  EXPECT_EQ(v.unit, "value");
  EXPECT_FALSE(valuesAreHu(v));
  const InitialWindow w = initialWindow(v);
  EXPECT_DOUBLE_EQ(w.wl.width, 3272.0);
  EXPECT_DOUBLE_EQ(w.wl.level, 1636.0);
  EXPECT_NE(w.source.find("modality unknown"), std::string::npos);
  EXPECT_EQ(valueUnit(v), "value");
  EXPECT_EQ(valueUnitLabel(v), "value");
  const CursorProbe p = probeAt(v, glm::dvec3(1, 1, 0), Interp::Nearest);
  EXPECT_EQ(p.unit, "value");
  EXPECT_DOUBLE_EQ(p.value, 1024.0);
}

TEST(ValueUnit, HuOnlyForValuesThatAreHu) {
  Volume ct = makeHeadPhantom(8);
  EXPECT_EQ(valueUnit(ct), "HU");
  EXPECT_EQ(valueUnitLabel(ct), "HU");

  Volume mr = makeHeadPhantom(8);  // as the DICOM importer labels an MR
  mr.modality = "MR";
  mr.unit = "MR signal (scanner units)";
  EXPECT_FALSE(valuesAreHu(mr));
  EXPECT_EQ(valueUnit(mr), "MR signal (scanner units)");  // readouts: what the file says
  EXPECT_EQ(valueUnitLabel(mr), "value");                 // a control's suffix: short

  Volume nifti = mr;  // a NIfTI of unknown modality
  nifti.modality.clear();
  nifti.unit = "scanner units";
  EXPECT_EQ(valueUnitLabel(nifti), "value");
  nifti.unit = "SUV";  // a unit the file states, short enough for a label
  EXPECT_EQ(valueUnitLabel(nifti), "SUV");

  EXPECT_EQ(rawValueUnit(RawLayout{}), "value");
  RawLayout scaled;
  scaled.slope = 62.5;  // the stent's quantised values back to HU
  EXPECT_EQ(rawValueUnit(scaled), "HU");
}

}  // namespace
