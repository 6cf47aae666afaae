// 4D series (issue 36): the beating-sphere phantom (10 phases, the sphere's radius known per
// phase) written by the project's writer, grouped into time points by Temporal Position
// Identifier, by Trigger Time alone, or by repeated positions in instance order; and the same
// phases as a 4D NIfTI (written by the NIfTI library) read at each time point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include "../io/formats/nifti_writer.h"
#include "../io/test_support.h"
#include "test_data.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

// Voxel centres inside a sphere of radius R mm about the volume's centre: what phase t
// should show (the phantom writes inside <= R exactly, so the count is exact).
size_t analyticCount(const BeatingSpherePhantom& p, double r) {
  size_t n = 0;
  for (int k = 0; k < p.dims.z; ++k)
    for (int j = 0; j < p.dims.y; ++j)
      for (int i = 0; i < p.dims.x; ++i) {
        const glm::dvec3 d = (glm::dvec3(i, j, k) - 0.5 * glm::dvec3(p.dims - 1)) * p.spacingMm;
        n += glm::length(d) <= r;
      }
  return n;
}

// Voxels of V above 100 HU (inside: 300 HU, outside: -50 HU).
size_t sphereCount(const Volume& v) {
  size_t n = 0;
  for (int16_t s : v.voxels) n += v.toPhysical(s) > 100.0;
  return n;
}

TEST(FourD, TenPhasesInTimeOrderWhicheverWayTheyAreMarked) {
  for (const char* timing : {"temporal", "trigger", "repeated"}) {
    SCOPED_TRACE(timing);
    test::TempDir dir;
    BeatingSpherePhantom p;
    p.timing = timing;
    writeBeatingSpherePhantom(dir.file("ct"), p);
    const std::vector<Volume> all = loadVolumeSeries(dir.file("ct"));
    ASSERT_EQ(all.size(), 10u);
    for (int t = 0; t < 10; ++t) {
      const Volume& v = all[size_t(t)];
      EXPECT_EQ(v.timePoint, t);
      EXPECT_EQ(v.timePoints, 10);
      EXPECT_EQ(v.dims, p.dims);
      EXPECT_EQ(v.spacingMm, p.spacingMm);
      EXPECT_EQ(sphereCount(v), analyticCount(p, p.radiusAt(t))) << "phase " << t;
    }
    // The phases differ: radius 24 mm at phase 0, 31.6 mm at phase 2 (24 + 8 sin 72 deg).
    EXPECT_GT(sphereCount(all[2]), sphereCount(all[0]) + 10000);
  }
}

// Phase 3's image at one position is lost. Named phases (Trigger Time) keep the others
// whole; unnamed ones (positions merely repeated) cannot be told apart: refused for the series.
TEST(FourD, AMissingImageStaysInItsOwnPhaseOrIsRefused) {
  for (const char* timing : {"trigger", "repeated"}) {
    SCOPED_TRACE(timing);
    test::TempDir dir;
    BeatingSpherePhantom p;
    p.dims = {32, 32, 16};
    p.timing = timing;
    writeBeatingSpherePhantom(dir.file("ct"), p);
    // Phase 3, slice 5: instance 3 * 16 + 5 + 1 = 54 ("trigger" numbers backwards: 160 - 53).
    const int instance = std::string(timing) == "trigger" ? 160 - 53 : 54;
    char name[32];
    std::snprintf(name, sizeof name, "CT%05d.dcm", instance);
    ASSERT_TRUE(std::filesystem::remove(dir.file("ct") + "/" + name));
    if (std::string(timing) == "repeated") {
      try {
        loadVolumeSeries(dir.file("ct"));
        ADD_FAILURE() << "uneven unnamed phases accepted";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot be split into time points reliably"),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    const std::vector<Volume> all = loadVolumeSeries(dir.file("ct"));
    ASSERT_EQ(all.size(), 10u);
    for (int t = 0; t < 10; ++t)
      if (t != 3) EXPECT_EQ(sphereCount(all[size_t(t)]), analyticCount(p, p.radiusAt(t))) << t;
    EXPECT_TRUE(test::anyContains(all[3].warnings, "1 slice(s) missing"));
  }
}

TEST(FourD, TimeOptionOpensThatPhase) {
  test::TempDir dir;
  BeatingSpherePhantom p;
  writeBeatingSpherePhantom(dir.file("ct"), p);
  for (int t : {0, 3, 7, 9}) {
    LoadOptions o;
    o.timePoint = t;
    const Volume v = loadVolume(dir.file("ct"), o);
    EXPECT_EQ(v.timePoint, t);
    EXPECT_EQ(v.timePoints, 10);
    EXPECT_EQ(sphereCount(v), analyticCount(p, p.radiusAt(t))) << "phase " << t;
  }
  // Without --time: time point 0, said in a warning.
  const Volume first = loadVolume(dir.file("ct"));
  EXPECT_EQ(first.timePoint, 0);
  EXPECT_TRUE(test::anyContains(first.warnings, "this is time point 0 of 0-9"));
}

TEST(FourD, TimeOutOfRangeSaysTheRange) {
  test::TempDir dir;
  BeatingSpherePhantom p;
  p.dims = {16, 16, 8};
  writeBeatingSpherePhantom(dir.file("ct"), p);
  LoadOptions o;
  o.timePoint = 10;
  try {
    loadVolume(dir.file("ct"), o);
    ADD_FAILURE() << "--time 10 accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_EQ(
        std::string(e.what()),
        dir.file("ct") + ": --time 10 is out of range: series 1 has 10 time point(s), 0 to 9");
  }
  // A 3D input has time point 0 only.
  o.timePoint = 1;
  try {
    loadVolume("", o);
    ADD_FAILURE() << "--time 1 accepted for the phantom";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--time 1 is out of range: it has 1 time point"),
              std::string::npos);
  }
}

// The beating sphere as one enhanced multi-frame file (the test's own, DCMTK): frames stored
// position-major (every phase of slice 0, then of slice 1 ...), each frame's phase only in its
// Frame Content Sequence's Temporal Position Index.
void writeEnhancedBeatingSphere(const std::string& path, const BeatingSpherePhantom& p) {
  DcmFileFormat file;
  DcmDataset* d = file.getDataset();
  auto put = [](DcmItem* item, const DcmTagKey& tag, const std::string& value) {
    item->putAndInsertString(tag, value.c_str());
  };
  char uid[100];
  put(d, DCM_SOPClassUID, UID_EnhancedCTImageStorage);
  put(d, DCM_SOPInstanceUID, dcmGenerateUniqueIdentifier(uid));
  put(d, DCM_SeriesInstanceUID, dcmGenerateUniqueIdentifier(uid));
  put(d, DCM_StudyInstanceUID, dcmGenerateUniqueIdentifier(uid));
  put(d, DCM_Modality, "CT");
  put(d, DCM_SeriesNumber, "3");
  put(d, DCM_ImageType, "ORIGINAL\\PRIMARY\\AXIAL\\NONE");
  const int frames = p.phases * p.dims.z;
  put(d, DCM_NumberOfFrames, std::to_string(frames));
  d->putAndInsertUint16(DCM_Rows, Uint16(p.dims.y));
  d->putAndInsertUint16(DCM_Columns, Uint16(p.dims.x));
  d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
  put(d, DCM_PhotometricInterpretation, "MONOCHROME2");
  d->putAndInsertUint16(DCM_BitsAllocated, 16);
  d->putAndInsertUint16(DCM_BitsStored, 16);
  d->putAndInsertUint16(DCM_HighBit, 15);
  d->putAndInsertUint16(DCM_PixelRepresentation, 1);
  DcmItem *shared = nullptr, *g = nullptr;
  d->findOrCreateSequenceItem(DCM_SharedFunctionalGroupsSequence, shared, 0);
  shared->findOrCreateSequenceItem(DCM_PixelMeasuresSequence, g, 0);
  put(g, DCM_PixelSpacing, std::to_string(p.spacingMm.y) + "\\" + std::to_string(p.spacingMm.x));
  put(g, DCM_SliceThickness, std::to_string(p.spacingMm.z));
  shared->findOrCreateSequenceItem(DCM_PlaneOrientationSequence, g, 0);
  put(g, DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
  shared->findOrCreateSequenceItem(DCM_PixelValueTransformationSequence, g, 0);
  put(g, DCM_RescaleSlope, "1");
  put(g, DCM_RescaleIntercept, "0");
  std::vector<Uint16> pixels;
  const glm::dvec3 origin = -0.5 * glm::dvec3(p.dims - 1) * p.spacingMm;
  for (int k = 0, f = 0; k < p.dims.z; ++k)
    for (int t = 0; t < p.phases; ++t, ++f) {
      DcmItem* frame = nullptr;
      d->findOrCreateSequenceItem(DCM_PerFrameFunctionalGroupsSequence, frame, f);
      frame->findOrCreateSequenceItem(DCM_PlanePositionSequence, g, 0);
      put(g, DCM_ImagePositionPatient,
          std::to_string(origin.x) + "\\" + std::to_string(origin.y) + "\\" +
              std::to_string(origin.z + k * p.spacingMm.z));
      frame->findOrCreateSequenceItem(DCM_FrameContentSequence, g, 0);
      put(g, DCM_TemporalPositionIndex, std::to_string(t + 1));
      for (int j = 0; j < p.dims.y; ++j)
        for (int i = 0; i < p.dims.x; ++i) {
          const glm::dvec3 c = (glm::dvec3(i, j, k) - 0.5 * glm::dvec3(p.dims - 1)) * p.spacingMm;
          pixels.push_back(
              Uint16(Sint16(glm::length(c) <= p.radiusAt(t) ? p.insideHu : p.outsideHu)));
        }
    }
  d->putAndInsertUint16Array(DCM_PixelData, pixels.data(), pixels.size());
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good()) << path;
}

TEST(FourD, EnhancedMultiFrameWithATemporalIndex) {
  test::TempDir dir;
  BeatingSpherePhantom p;
  p.dims = {32, 32, 12};
  writeEnhancedBeatingSphere(dir.file("enhanced.dcm"), p);
  const std::vector<Volume> all = loadVolumeSeries(dir.file("enhanced.dcm"));
  ASSERT_EQ(all.size(), 10u);
  for (int t = 0; t < 10; ++t) {
    EXPECT_EQ(all[size_t(t)].dims, p.dims);
    EXPECT_EQ(sphereCount(all[size_t(t)]), analyticCount(p, p.radiusAt(t))) << "phase " << t;
  }
}

// The 4D NIfTI of the DICOM phases (LPS -> RAS in the sform) gives, at each time point, the
// very voxels and geometry of that DICOM phase.
TEST(FourD, NiftiTimePointEqualsTheDicomPhase) {
  test::TempDir dir;
  BeatingSpherePhantom p;
  p.dims = {32, 24, 16};
  writeBeatingSpherePhantom(dir.file("ct"), p);
  const std::vector<Volume> dicom = loadVolumeSeries(dir.file("ct"));
  ASSERT_EQ(dicom.size(), 10u);
  const Volume& v0 = dicom[0];
  test::NiftiSpec spec;
  spec.dims = {p.dims.x, p.dims.y, p.dims.z, 10};
  spec.sformCode = 1;
  for (int r = 0; r < 3; ++r) {
    const double flip = r < 2 ? -1.0 : 1.0;  // L, P -> R, A
    for (int c = 0; c < 3; ++c) spec.sform[r][c] = flip * v0.direction[c][r] * v0.spacingMm[c];
    spec.sform[r][3] = flip * v0.originMm[r];
    spec.pixdim[r] = v0.spacingMm[r];
  }
  for (const auto& v : dicom)
    for (int16_t s : v.voxels) spec.values.push_back(v.toPhysical(s));
  const std::string nii = dir.file("beating.nii.gz");
  test::writeNifti(nii, spec);
  for (int t : {0, 2, 5, 9}) {
    LoadOptions o;
    o.timePoint = t;
    const Volume n = loadVolume(nii, o);
    const Volume& d = dicom[size_t(t)];
    EXPECT_EQ(n.timePoint, t);
    EXPECT_EQ(n.timePoints, 10);
    ASSERT_EQ(n.dims, d.dims);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(n.originMm[a], d.originMm[a], 1e-4) << a;  // float32 sform
      EXPECT_NEAR(n.spacingMm[a], d.spacingMm[a], 1e-5) << a;
    }
    size_t differ = 0;
    for (size_t i = 0; i < n.voxels.size(); ++i)
      differ += n.toPhysical(n.voxels[i]) != d.toPhysical(d.voxels[i]);
    EXPECT_EQ(differ, 0u) << "time point " << t;
    EXPECT_EQ(sphereCount(n), analyticCount(p, p.radiusAt(t)));
  }
  LoadOptions o;
  o.timePoint = 10;
  try {
    loadVolume(nii, o);
    ADD_FAILURE() << "--time 10 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--time 10 is out of range: the file has 10 time "
                                         "point(s), 0 to 9"),
              std::string::npos);
  }
  EXPECT_EQ(loadVolumeSeries(nii).size(), 10u);
}

}  // namespace
}  // namespace voxray
