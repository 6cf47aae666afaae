// NIfTI headers written by the NIfTI library itself: the sform/qform rule, RAS to LPS,
// left/right, units, sample types, scl_slope/scl_inter, 4D and NIfTI-2.
#include <cmath>

#include "format_test_support.h"
#include "nifti_writer.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using test::NiftiSpec;
using test::TempDir;

// sform: RAS steps 2, 3, 4 mm, offset (10, 20, 30). qform: identity rotation, 1 mm voxels,
// offset (-5, -6, -7). The two differ in every geometric field.
NiftiSpec sformAndQform(int sformCode, int qformCode) {
  NiftiSpec s;
  s.sformCode = sformCode;
  s.qformCode = qformCode;
  s.sform[0][0] = 2, s.sform[1][1] = 3, s.sform[2][2] = 4;
  s.sform[0][3] = 10, s.sform[1][3] = 20, s.sform[2][3] = 30;
  s.qoffset[0] = -5, s.qoffset[1] = -6, s.qoffset[2] = -7;
  return s;
}

Volume writeAndLoad(const NiftiSpec& spec, const std::string& name = "v.nii") {
  TempDir dir;
  test::writeNifti(dir.file(name), spec);
  return loadVolume(dir.file(name));
}

const glm::dmat3 kRasInLps(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1));

TEST(FormatsNifti, SformWinsWhenItsCodeIsSet) {
  for (int qformCode : {0, 1}) {
    const Volume v = writeAndLoad(sformAndQform(1, qformCode));
    EXPECT_EQ(v.spacingMm, glm::dvec3(2, 3, 4));
    EXPECT_EQ(v.originMm, glm::dvec3(-10, -20, 30));
    EXPECT_EQ(v.direction, kRasInLps);
  }
  const Volume aligned = writeAndLoad(sformAndQform(2, 1));  // NIFTI_XFORM_ALIGNED_ANAT
  EXPECT_EQ(aligned.spacingMm, glm::dvec3(2, 3, 4));
}

TEST(FormatsNifti, QformWhenSformCodeIsZero) {
  const Volume v = writeAndLoad(sformAndQform(0, 1));
  EXPECT_EQ(v.spacingMm, glm::dvec3(1, 1, 1));
  EXPECT_EQ(v.originMm, glm::dvec3(5, 6, -7));
  EXPECT_EQ(v.direction, kRasInLps);
  EXPECT_TRUE(v.warnings.empty());
}

TEST(FormatsNifti, RotatedQformBecomesLps) {
  NiftiSpec s = sformAndQform(0, 1);
  s.quatern[2] = std::sqrt(0.5);  // 90 degrees about z: i runs along RAS +y (anterior)
  s.pixdim[0] = 0.5;
  const Volume v = writeAndLoad(s);
  EXPECT_NEAR(v.spacingMm.x, 0.5, 1e-6);
  EXPECT_NEAR(glm::length(v.direction[0] - glm::dvec3(0, -1, 0)), 0.0, 1e-6);  // anterior
  EXPECT_NEAR(glm::length(v.direction[1] - glm::dvec3(1, 0, 0)), 0.0, 1e-6);   // RAS -x: left
}

TEST(FormatsNifti, NoTransformWarnsAndUsesPixdim) {
  NiftiSpec s = sformAndQform(0, 0);
  s.pixdim[2] = 2.5;
  const Volume v = writeAndLoad(s);
  EXPECT_EQ(v.spacingMm, glm::dvec3(1, 1, 2.5));
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_THAT(v.warnings[0], testing::HasSubstr("neither sform nor qform"));
}

// A bright voxel at RAS x = -2 mm (the patient's left) is at LPS x = +2 mm (left) after import.
TEST(FormatsNifti, PatientLeftStaysLeft) {
  NiftiSpec s = sformAndQform(1, 0);
  s.dims = {5, 3, 2};
  s.sform[0][0] = -1, s.sform[1][1] = 1, s.sform[2][2] = 1;  // i toward the patient's left
  s.sform[0][3] = 0, s.sform[1][3] = 0, s.sform[2][3] = 0;
  s.values.assign(30, 0.0);
  s.values[2] = 1000;  // i = 2: RAS x = -2
  const Volume v = writeAndLoad(s);
  const auto it = std::max_element(v.voxels.begin(), v.voxels.end());
  const auto i = size_t(it - v.voxels.begin());
  const glm::dvec3 p = test::voxelCentre(v, glm::dvec3(double(i % 5), 0, 0));
  EXPECT_EQ(p, glm::dvec3(2, 0, 0));
  EXPECT_EQ(v.toPhysical(*it), 1000.0);
}

TEST(FormatsNifti, UnitsBecomeMillimetres) {
  NiftiSpec s = sformAndQform(1, 0);
  s.xyzUnits = 1;  // NIFTI_UNITS_METER
  const Volume v = writeAndLoad(s);
  EXPECT_EQ(v.spacingMm, glm::dvec3(2000, 3000, 4000));
}

struct TypeCase {
  int datatype;
  const char* name;
  std::vector<double> values;  // 24 values
  double precision;            // largest allowed error of a physical value
  bool warns;
};

std::vector<double> spread(double lo, double hi) {
  std::vector<double> v;
  for (int i = 0; i < 24; ++i) v.push_back(lo + (hi - lo) * i / 23.0);
  return v;
}

TEST(FormatsNifti, EverySampleTypeKeepsItsValues) {
  std::vector<double> whole = spread(0, 23), fractions;
  for (int i = 0; i < 24; ++i) fractions.push_back(-3.0 + 0.25 * i);
  std::vector<double> wide = spread(-100000, 100000);
  for (auto& x : wide) x = std::round(x);
  const std::vector<TypeCase> cases = {
      {2,
       "u8",
       {0, 255, 7, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21},
       0.0,
       false},
      {256,
       "i8",
       {-128, 127, -1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20},
       0.0,
       false},
      {512,
       "u16",
       {0,  65535, 40000, 3,  4,  5,  6,  7,  8,  9,  10, 11,
        12, 13,    14,    15, 16, 17, 18, 19, 20, 21, 22, 23},
       0.0,
       true},  // wider than int16 by 0: an intercept shift keeps it exact
      {4, "i16", whole, 0.0, false},
      {768, "u32", whole, 0.0, false},
      {8, "i32", wide, 2.0, true},        // 200001 values over 65536 levels: step 4, error <= 2
      {16, "f32", fractions, 0.0, true},  // quarter steps are a power of two: exact
      {64, "f64", fractions, 0.0, true},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    NiftiSpec s;
    s.qformCode = 1;  // a plain 1 mm grid, so only the value storage may warn
    s.datatype = c.datatype;
    s.values = c.values;
    const Volume v = writeAndLoad(s);
    EXPECT_EQ(v.sourceType, c.name);
    for (int i = 0; i < 24; ++i)
      EXPECT_NEAR(v.toPhysical(v.voxels[size_t(i)]), c.values[size_t(i)], c.precision) << i;
    EXPECT_EQ(!v.warnings.empty(), c.warns);
  }
}

TEST(FormatsNifti, SclSlopeAndInterGivePhysicalValues) {
  NiftiSpec s;
  s.qformCode = 1;
  s.sclSlope = 2, s.sclInter = -1024;
  const Volume v = writeAndLoad(s);  // stored 0..23
  for (int i = 0; i < 24; ++i) EXPECT_EQ(v.toPhysical(v.voxels[size_t(i)]), 2.0 * i - 1024.0);
  EXPECT_EQ(v.slope, 1.0) << "whole values that fit int16 are stored exactly";
  EXPECT_TRUE(v.warnings.empty());
  // A fractional slope on integer samples that fit int16: the file's own scale, exactly.
  NiftiSpec fine;
  fine.qformCode = 1;
  fine.sclSlope = 0.001;
  fine.sclInter = 0.5;
  const Volume f = writeAndLoad(fine);
  const double slope32 = double(0.001f);  // NIfTI-1 keeps scl_slope as float32
  EXPECT_EQ(f.slope, slope32);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(f.toPhysical(f.voxels[size_t(i)]), slope32 * i + 0.5);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_THAT(f.warnings[0], testing::HasSubstr("the file's own scale"));
}

TEST(FormatsNifti, FourDimensionsGiveTheFirstVolumeWithAWarning) {
  NiftiSpec s;
  s.qformCode = 1;
  s.dims = {4, 3, 2, 5};
  const Volume v = writeAndLoad(s, "fmri.nii.gz");
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
  EXPECT_EQ(v.toPhysical(v.voxels.back()), 23.0);  // volume 1 ends at index 23
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_THAT(v.warnings[0], testing::HasSubstr("volume 1 of 5"));
}

TEST(FormatsNifti, NiftiTwoReadsLikeNiftiOne) {
  for (bool nifti2 : {false, true}) {
    NiftiSpec s = sformAndQform(1, 1);
    s.nifti2 = nifti2;
    const Volume v = writeAndLoad(s, nifti2 ? "v2.nii.gz" : "v1.nii.gz");
    EXPECT_EQ(v.spacingMm, glm::dvec3(2, 3, 4));
    EXPECT_EQ(v.originMm, glm::dvec3(-10, -20, 30));
    EXPECT_EQ(v.toPhysical(v.voxels[23]), 23.0);
  }
}

TEST(FormatsNifti, ShearedSformFallsBackToTheQform) {
  NiftiSpec s = sformAndQform(1, 1);
  s.sform[0][1] = 1.5;  // j leans along x: not a rectangular grid
  Volume v = writeAndLoad(s);
  EXPECT_EQ(v.spacingMm, glm::dvec3(1, 1, 1));
  EXPECT_THAT(v.warnings.at(0), testing::HasSubstr("sheared"));
  s.qformCode = 0;
  const std::string m = test::errorMessage([&] { writeAndLoad(s); });
  EXPECT_THAT(m, testing::HasSubstr("sheared"));
}

// Issue 41 item 2: NIfTI has no modality field; a header whose descrip or intent_name says
// CT or HU, PET or SUV, MR, names it, conservatively (a whole word, nothing contradicting).
TEST(FormatsNifti, DescripAndIntentNameHintTheModalityAndUnit) {
  struct Case {
    std::string descrip, intentName, modality, unit;
  };
  const Case cases[] = {
      {"", "", "", "scanner units"},  // nothing said: unknown, as before
      {"CT head 1.25 mm", "", "CT", "HU"},
      {"", "HU", "CT", "HU"},
      {"values in Hounsfield units", "", "CT", "HU"},
      {"PET/CT FDG", "SUVbw", "PT", "SUV"},  // a PET/CT's PET image says CT too
      {"PET", "", "PT", "scanner units"},
      {"T1w MPRAGE", "", "MR", "scanner units"},
      {"MR after CT", "", "", "scanner units"},           // contradicting: nothing is claimed
      {"Hu Wei, sub-01", "", "", "scanner units"},        // a name, not the unit
      {"ACT pipeline; Doctor", "", "", "scanner units"},  // CT only as a whole word
  };
  for (const Case& c : cases) {
    NiftiSpec s;
    s.descrip = c.descrip;
    s.intentName = c.intentName;
    const Volume v = writeAndLoad(s);
    EXPECT_EQ(v.modality, c.modality) << c.descrip << " | " << c.intentName;
    EXPECT_EQ(v.unit, c.unit) << c.descrip << " | " << c.intentName;
  }
}

}  // namespace
}  // namespace voxray
