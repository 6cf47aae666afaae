// Label-map files of issue 34: what Voxray writes, it reads back voxel for voxel, and the
// independent readers (nibabel, pynrrd, highdicom, dciodvfy) read the same.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "command_run.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"
#include "voxray/io/segment_files.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct TempFolder {
  fs::path path =
      fs::temp_directory_path() / ("voxray-segfiles-" + std::to_string(::getpid()) + "-" +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempFolder() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

// An oblique, anisotropic grid (rotated 30 degrees about z), so a swapped axis or a lost sign
// (LPS vs RAS) moves voxels.
Volume obliqueVolume() {
  Volume v;
  v.dims = {24, 20, 10};
  v.spacingMm = {0.7, 0.8, 2.5};
  v.originMm = {-80.5, 40.25, 900.0};
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  v.direction = glm::dmat3(glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1));
  v.voxels.assign(v.voxelCount(), 0);
  v.modality = "CT";
  StudyIdentity& id = v.study;
  id.patientName = "Doe^Jane";
  id.patientId = "PID-42";
  id.studyInstanceUid = "1.2.826.0.1.3680043.8.498.100";
  id.seriesInstanceUid = "1.2.826.0.1.3680043.8.498.101";
  id.frameOfReferenceUid = "1.2.826.0.1.3680043.8.498.102";
  id.studyDate = "20260101";
  id.sopClassUid = "1.2.840.10008.5.1.4.1.1.2";
  for (int k = 0; k < v.dims.z; ++k)
    id.sliceSopInstanceUids.push_back("1.2.826.0.1.3680043.8.498.2." + std::to_string(k + 1));
  return v;
}

// A ball (label 1, coded pelvis) and a slab (label 3, free text); label 2 is not used.
Segmentation twoSegments(const Volume& v) {
  Segmentation seg = emptySegmentation(v);
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const glm::dvec3 d = (glm::dvec3(x, y, z) - glm::dvec3(10, 9, 4)) * v.spacingMm;
        if (glm::length(d) < 5.0) seg.labels[seg.grid.index(x, y, z)] = 1;
        if (z >= 7 && z <= 8 && x >= 15) seg.labels[seg.grid.index(x, y, z)] = 3;
      }
  Segment bone;
  bone.label = 1;
  bone.name = "Pelvis";
  bone.colour = {0.9f, 0.85f, 0.7f};
  bone.type = {"12921003", "SCT", "Pelvis"};
  Segment table;
  table.label = 3;
  table.name = "CT table";
  table.colour = {0.2f, 0.4f, 1.0f};
  table.category = {"", "", "Physical object"};
  table.type = {"", "", "Table"};
  seg.segments = {bone, table};
  return seg;
}

std::map<int, int> countsOf(const Segmentation& seg) {
  std::map<int, int> counts;
  for (uint8_t l : seg.labels)
    if (l) ++counts[l];
  return counts;
}

json countsJson(const Segmentation& seg) {
  json j = json::object();
  for (auto [label, n] : countsOf(seg)) j[std::to_string(label)] = n;
  return j;
}

// Runs the independent checker; fails the test with its output unless every check holds.
void checkWithPython(const std::string& mode, const std::string& file, const std::string& arg) {
  ASSERT_TRUE(fs::exists(VOXRAY_PYTHON))
      << VOXRAY_PYTHON << " is missing: run scripts/bootstrap (it makes the venv of test readers)";
  const test::CommandResult r =
      test::runCommand(std::string(VOXRAY_PYTHON) + " " + VOXRAY_SEGMENT_CHECKER + " " + mode +
                       " '" + file + "' '" + arg + "' 2>&1");
  ASSERT_NE(r.exitCode, 3) << r.output << "run scripts/bootstrap";
  EXPECT_EQ(r.exitCode, 0) << r.output;
  if (!r.output.empty()) std::cout << mode << " check: " << r.output;
}

std::string writeJson(const TempFolder& dir, const json& j) {
  const std::string path = dir / "expected.json";
  std::ofstream(path) << j.dump();
  return path;
}

void expectError(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one saying \"" << part << "\"";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

void expectSameSegments(const Segmentation& got, const Segmentation& want, float colourTolerance) {
  ASSERT_EQ(got.segments.size(), want.segments.size());
  for (size_t i = 0; i < want.segments.size(); ++i) {
    const Segment &g = got.segments[i], &w = want.segments[i];
    EXPECT_EQ(g.name, w.name);
    EXPECT_EQ(int(g.label), int(w.label));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.colour[c], w.colour[c], colourTolerance) << w.name;
    EXPECT_EQ(g.type.value, w.type.value) << w.name;
    EXPECT_EQ(g.type.scheme, w.type.scheme) << w.name;
    EXPECT_EQ(g.type.meaning, w.type.meaning) << w.name;
    EXPECT_EQ(g.category.meaning, w.category.meaning) << w.name;
  }
}

json rasAffine(const VoxelGrid& g) {
  json a = json::array();
  const double flip[3] = {-1, -1, 1};
  for (int r = 0; r < 3; ++r) {
    json row = json::array();
    for (int c = 0; c < 3; ++c) row.push_back(flip[r] * g.direction[c][r] * g.spacingMm[c]);
    row.push_back(flip[r] * g.originMm[r]);
    a.push_back(row);
  }
  a.push_back({0, 0, 0, 1});
  return a;
}

// What highdicom must find in a SEG of SEG (segments numbered 1.. in order): each frame at
// its slice's position and source image, and the label map (renumbered) voxel for voxel.
json segExpectation(const TempFolder& dir, const Volume& v, const Segmentation& seg,
                    const json& segments) {
  json frames = json::array();
  const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
  std::vector<uint8_t> renumbered(seg.labels.size(), 0);
  json counts = json::object();
  int number = 0;
  for (const Segment& s : seg.segments) {
    ++number;
    int count = 0;
    for (size_t i = 0; i < seg.labels.size(); ++i)
      if (seg.labels[i] == s.label) {
        renumbered[i] = uint8_t(number);
        ++count;
      }
    counts[std::to_string(number)] = count;
    for (int k = 0; k < v.dims.z; ++k) {
      bool has = false;
      for (size_t i = 0; i < slice; ++i) has |= seg.labels[size_t(k) * slice + i] == s.label;
      if (!has) continue;
      const glm::dvec3 p = seg.grid.toPatient(glm::dvec3(0, 0, k));
      frames.push_back({{"segment", number},
                        {"slice", k},
                        {"position", {p.x, p.y, p.z}},
                        {"source", v.study.sliceSopInstanceUids[size_t(k)]}});
    }
  }
  const std::string raw = dir / "labels.raw";
  std::ofstream(raw, std::ios::binary)
      .write(reinterpret_cast<const char*>(renumbered.data()), std::streamsize(renumbered.size()));
  return {{"frame_of_reference", v.study.frameOfReferenceUid},
          {"study", v.study.studyInstanceUid},
          {"series", v.study.seriesInstanceUid},
          {"segments", segments},
          {"counts", counts},
          {"frames", frames},
          {"dims", {v.dims.x, v.dims.y, v.dims.z}},
          {"labels_raw", raw}};
}

TEST(SegmentFiles, ANiftiLabelMapReadsBackVoxelForVoxelAtTheVolumesRasAffine) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  const std::string path = dir / "labels.nii.gz";
  writeSegmentationNifti(path, seg);
  const Segmentation back = readSegmentationFile(path, v);
  EXPECT_EQ(back.labels, seg.labels);
  ASSERT_EQ(back.segments.size(), 2u);  // NIfTI has no names: one segment per label found
  EXPECT_EQ(int(back.segments[0].label), 1);
  EXPECT_EQ(int(back.segments[1].label), 3);
  EXPECT_EQ(back.segments[1].name, "Label 3");
  checkWithPython("nifti", path,
                  writeJson(dir, {{"dims", {24, 20, 10}},
                                  {"affine", rasAffine(seg.grid)},
                                  {"counts", countsJson(seg)}}));
}

TEST(SegmentFiles, ASegNrrdKeepsNamesColoursCodesAndLabelValuesForSlicer) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  const std::string path = dir / "labels.seg.nrrd";
  writeSegNrrd(path, seg);
  const Segmentation back = readSegmentationFile(path, v);
  EXPECT_EQ(back.labels, seg.labels);
  expectSameSegments(back, seg, 1e-6f);  // written with 6 significant digits
  json directions = json::array();
  for (int a = 0; a < 3; ++a)
    directions.push_back({seg.grid.direction[a].x * seg.grid.spacingMm[a],
                          seg.grid.direction[a].y * seg.grid.spacingMm[a],
                          seg.grid.direction[a].z * seg.grid.spacingMm[a]});
  json segments = json::array();
  for (const Segment& s : seg.segments)
    segments.push_back({{"name", s.name},
                        {"label", s.label},
                        {"colour", {s.colour.r, s.colour.g, s.colour.b}},
                        {"type_code", s.type.value.empty() ? "^^" + s.type.meaning
                                                           : s.type.scheme + "^" + s.type.value}});
  checkWithPython("nrrd", path,
                  writeJson(dir, {{"dims", {24, 20, 10}},
                                  {"directions", directions},
                                  {"origin", {v.originMm.x, v.originMm.y, v.originMm.z}},
                                  {"counts", countsJson(seg)},
                                  {"segments", segments}}));
}

TEST(SegmentFiles, ASegNrrdCroppedToItsSegmentsIsPlacedOnItsVolume) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  // Slicer crops to the segments' box: the file is voxels 2..21 x 3..17 x 1..8 of the volume.
  Segmentation box;
  box.grid = seg.grid;
  box.grid.dims = {20, 15, 8};
  box.grid.originMm = seg.grid.toPatient(glm::dvec3(2, 3, 1));
  box.segments = seg.segments;
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 15; ++y)
      for (int x = 0; x < 20; ++x)
        box.labels.push_back(seg.labels[seg.grid.index(x + 2, y + 3, z + 1)]);
  const std::string path = dir / "cropped.seg.nrrd";
  writeSegNrrd(path, box);
  const Segmentation back = readSegmentationFile(path, v);
  Segmentation inside = emptySegmentation(v);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 15; ++y)
      for (int x = 0; x < 20; ++x)
        inside.labels[seg.grid.index(x + 2, y + 3, z + 1)] =
            seg.labels[seg.grid.index(x + 2, y + 3, z + 1)];
  EXPECT_EQ(back.labels, inside.labels);
}

TEST(SegmentFiles, ADicomSegReadsBackVoxelForVoxelWithNamesColoursAndCodes) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  const std::string path = dir / "labels.dcm";
  DicomSegOptions options;
  options.algorithm = DicomSegOptions::Algorithm::Manual;
  const std::string uid = writeDicomSeg(path, seg, v.study, options).sopInstanceUid;
  EXPECT_FALSE(uid.empty());
  const Segmentation back = readSegmentationFile(path, v);
  // The SEG numbers its segments 1, 2: label 3 comes back as 2, the same voxels.
  ASSERT_EQ(back.segments.size(), 2u);
  EXPECT_EQ(int(back.segments[1].label), 2);
  Segmentation renumbered = seg;
  renumbered.segments[1].label = 2;
  for (auto& l : renumbered.labels)
    if (l == 3) l = 2;
  EXPECT_EQ(back.labels, renumbered.labels);
  // CIELab in 16 bits, through DCMTK's conversion: a few thousandths of sRGB.
  expectSameSegments(back, renumbered, 0.005f);

  // highdicom: every frame at its slice's position, referencing its slice's image.
  json segments = json::array();
  segments.push_back({{"number", 1},
                      {"name", "Pelvis"},
                      {"type_code", "12921003"},
                      {"category_code", "91723000"},
                      {"algorithm", "MANUAL"}});
  segments.push_back({{"number", 2},
                      {"name", "CT table"},
                      {"type_code", "VOXRAY-FREE-TEXT"},
                      {"category_code", "VOXRAY-FREE-TEXT"},
                      {"algorithm", "MANUAL"}});
  checkWithPython("seg", path, writeJson(dir, segExpectation(dir, v, seg, segments)));
}

TEST(SegmentFiles, DicomSegFramesWhoseBitsDoNotFillWholeBytesReadBack) {
  // 13 x 11 = 143 pixels: binary frames are packed one after another, so frame 2 starts in
  // the middle of a byte.
  TempFolder dir;
  Volume v = obliqueVolume();
  v.dims = {13, 11, 10};
  v.voxels.assign(v.voxelCount(), 0);
  Segmentation seg = emptySegmentation(v);
  for (size_t i = 0; i < seg.labels.size(); ++i) seg.labels[i] = (i * 7 + i / 5) % 3 == 0 ? 1 : 0;
  Segment s;
  s.name = "Pattern";
  seg.segments = {s};
  writeDicomSeg(dir / "odd.dcm", seg, v.study);
  EXPECT_EQ(readSegmentationFile(dir / "odd.dcm", v).labels, seg.labels);
  json segments = json::array();
  segments.push_back({{"number", 1},
                      {"name", "Pattern"},
                      {"type_code", "85756007"},
                      {"category_code", "91723000"},
                      {"algorithm", "SEMIAUTOMATIC"}});
  checkWithPython("seg", dir / "odd.dcm", writeJson(dir, segExpectation(dir, v, seg, segments)));
}

// dciodvfy checks the object against the IOD; its output names each problem "Error - ...".
void expectNoIodError(const std::string& path) {
  const std::string out = test::runCommand("dciodvfy '" + path + "' 2>&1").output;
  ASSERT_NE(out.find("Segmentation"), std::string::npos) << "dciodvfy did not run:\n" << out;
  EXPECT_EQ(out.find("Error"), std::string::npos) << out;
  std::cout << "dciodvfy: " << out;  // warnings, if any, for the reader of the log
}

TEST(SegmentFiles, DciodvfyFindsNoErrorInTheDicomSeg) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const std::string path = dir / "labels.dcm";
  writeDicomSeg(path, twoSegments(v), v.study);
  expectNoIodError(path);
}

TEST(SegmentFiles, AnExistingFileIsKeptUnlessOverwriteIsAllowedAndNoTemporaryFileRemains) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  const std::string path = dir / "labels.seg.nrrd";
  std::ofstream(path) << "mine";
  expectError([&] { writeSegNrrd(path, seg); }, "exists already");
  EXPECT_EQ(fs::file_size(path), 4u);
  writeSegNrrd(path, seg, true);
  EXPECT_EQ(readSegmentationFile(path, v).labels, seg.labels);
  expectError([&] { writeSegmentationNifti(dir / "no-such-folder/x.nii", seg); }, "does not exist");
  int files = 0;
  for (auto& e : fs::directory_iterator(dir.path)) files += e.path().filename() != "expected.json";
  EXPECT_EQ(files, 1) << "a temporary file was left beside the output";
}

TEST(SegmentFiles, AnEmptySegmentIsNotWrittenAsDicomSegAndNothingIsLeft) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  Segmentation seg = twoSegments(v);
  Segment empty;
  empty.label = 7;
  empty.name = "Liver";
  seg.segments.push_back(empty);
  const std::string path = dir / "labels.dcm";
  expectError([&] { writeDicomSeg(path, seg, v.study); }, "\"Liver\" is empty (0 voxels)");
  EXPECT_TRUE(fs::is_empty(dir.path));
  // NRRD keeps the empty segment with Slicer's empty extent; it reads back by name.
  writeSegNrrd(dir / "labels.seg.nrrd", seg);
  const Segmentation back = readSegmentationFile(dir / "labels.seg.nrrd", v);
  ASSERT_EQ(back.segments.size(), 3u);
  EXPECT_EQ(back.segments[2].name, "Liver");
}

TEST(SegmentFiles, ALabelMapOnAnotherGridIsRefusedNamingTheDifference) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  writeSegmentationNifti(dir / "labels.nii", seg);
  writeSegNrrd(dir / "labels.seg.nrrd", seg);
  Volume finer = v;
  finer.spacingMm.z = 1.25;
  expectError([&] { readSegmentationFile(dir / "labels.nii", finer); },
              "its spacing is (0.7, 0.8, 2.5) mm, the volume's (0.7, 0.8, 1.25) mm");
  Volume shifted = v;
  shifted.originMm.z += 1.0;  // a millimetre: not on one of the volume's slices
  expectError([&] { readSegmentationFile(dir / "labels.seg.nrrd", shifted); },
              "its first voxel lies at (-80.5, 40.25, 900) mm (LPS), the volume's at "
              "(-80.5, 40.25, 901) mm");
  Volume other = v;  // 20 rows cannot lie in 18
  other.dims = {24, 18, 10};
  expectError([&] { readSegmentationFile(dir / "labels.nii", other); },
              "its size is 24x20x10 voxels, the volume's 24x18x10");
}

TEST(SegmentFiles, ADicomSegOfAnotherSeriesOrGridIsRefused) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const std::string path = dir / "labels.dcm";
  writeDicomSeg(path, twoSegments(v), v.study);
  Volume other = v;
  other.study.seriesInstanceUid = "1.2.826.0.1.3680043.8.498.999";
  expectError([&] { readSegmentationFile(path, other); },
              "made on another series (it references 1.2.826.0.1.3680043.8.498.101");
  Volume moved = v;
  moved.originMm.z += 1.0;
  expectError([&] { readSegmentationFile(path, moved); }, "which is not on a slice of the volume");
  Volume raw = v;
  raw.study = {};
  expectError([&] { readSegmentationFile(path, raw); }, "was not read from DICOM");
  StudyIdentity none;
  expectError([&] { writeDicomSeg(dir / "x.dcm", twoSegments(v), none); },
              "this volume has none (it was not read from DICOM)");
}

TEST(SegmentFiles, TruncatedFilesAreRefusedWithAMessage) {
  TempFolder dir;
  const Volume v = obliqueVolume();
  const Segmentation seg = twoSegments(v);
  writeDicomSeg(dir / "a.dcm", seg, v.study);
  writeSegmentationNifti(dir / "a.nii", seg);
  writeSegNrrd(dir / "a.seg.nrrd", seg);
  for (const char* name : {"a.dcm", "a.nii", "a.seg.nrrd"})
    fs::resize_file(dir / name, fs::file_size(dir / name) / 2);
  expectError([&] { readSegmentationFile(dir / "a.dcm", v); }, "a.dcm: ");
  expectError([&] { readSegmentationFile(dir / "a.nii", v); }, "damaged or truncated");
  expectError([&] { readSegmentationFile(dir / "a.seg.nrrd", v); }, "cannot be read as NRRD");
  std::ofstream(dir / "a.txt") << "hello";
  expectError([&] { readSegmentationFile(dir / "a.txt", v); }, "is neither NIfTI, NRRD nor DICOM");
}

TEST(SegmentFiles, AnImageOpenedAsALabelMapIsRefusedNamingItsValue) {
  // A CT in HU is not a label map: 1000 is no label (0..255). Label 200 in 16 bits is one.
  TempFolder dir;
  Volume v;
  v.dims = {4, 3, 2};
  v.spacingMm = {1.0, 1.0, 2.0};
  v.originMm = {10, 20, 30};
  v.voxels.assign(v.voxelCount(), 0);
  const auto write = [&](const std::string& name, int16_t value) {
    std::ofstream f(dir / name, std::ios::binary);
    f << "NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
         "sizes: 4 3 2\nspace directions: (1,0,0) (0,1,0) (0,0,2)\nspace origin: (10,20,30)\n"
         "endian: little\nencoding: raw\n\n";
    std::vector<int16_t> data(24, 0);
    data[5] = value;
    f.write(reinterpret_cast<const char*>(data.data()), 48);
  };
  write("ct.nrrd", 1000);
  expectError([&] { readSegmentationFile(dir / "ct.nrrd", v); },
              "holds the value 1000, which is not a label (whole numbers 0 to 255)");
  write("labels.nrrd", 200);
  const Segmentation seg = readSegmentationFile(dir / "labels.nrrd", v);
  EXPECT_EQ(int(seg.labels[5]), 200);
  ASSERT_EQ(seg.segments.size(), 1u);
  EXPECT_EQ(seg.segments[0].name, "Label 200");
}

TEST(SegmentFiles, ASegOfTheRealPelvisSeriesReferencesEachSourceImage) {
  const std::string series = std::string(VOXRAY_DATA_DIR) + "/dicom/ct-visible-human-pelvis";
  ASSERT_TRUE(fs::is_directory(series)) << series << " is missing (see /work/shared/data)";
  const Volume v = importDicom(series);
  ASSERT_EQ(v.study.sliceSopInstanceUids.size(), size_t(v.dims.z));
  // Bone: at least 300 HU, in slices 40..59 (a SEG of 20 slices keeps the test quick).
  Segmentation seg = emptySegmentation(v);
  const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
  for (size_t k = 40; k < 60; ++k)
    for (size_t i = 0; i < slice; ++i)
      if (v.toPhysical(v.voxels[k * slice + i]) >= 300) seg.labels[k * slice + i] = 1;
  Segment bone;
  bone.name = "Bone";
  bone.type = {"272673000", "SCT", "Bone"};
  seg.segments = {bone};
  TempFolder dir;
  const std::string path = dir / "pelvis-seg.dcm";
  writeDicomSeg(path, seg, v.study);
  const Segmentation back = readSegmentationFile(path, v);
  EXPECT_EQ(back.labels, seg.labels);
  checkWithPython("source", path, series);
  expectNoIodError(path);
}

}  // namespace
}  // namespace voxray

namespace voxray {
namespace {

TEST(SegmentFiles, ASegOfAResampledSeriesReferencesItsStudyAndFrameOfReferenceOnly) {
  // Gantry tilt: the volume's slices are resampled, none is a file's image, so the loader
  // keeps no per-slice instances and the SEG references no image it does not lie on.
  const std::string series = std::string(VOXRAY_DATA_DIR) + "/dicom/ct-ge-tilt";
  ASSERT_TRUE(fs::is_directory(series)) << series << " is missing (see /work/shared/data)";
  const Volume v = importDicom(series);
  EXPECT_TRUE(v.study.sliceSopInstanceUids.empty());
  EXPECT_EQ(v.study.sopClassUid, "1.2.840.10008.5.1.4.1.1.2");  // CT Image Storage
  Segmentation seg = emptySegmentation(v);
  for (size_t i = 0; i < seg.labels.size(); ++i)
    if (v.toPhysical(v.voxels[i]) >= 300) seg.labels[i] = 1;
  Segment bone;
  bone.name = "Skull";
  seg.segments = {bone};
  TempFolder dir;
  const std::string path = dir / "tilt-seg.dcm";
  writeDicomSeg(path, seg, v.study);
  EXPECT_EQ(readSegmentationFile(path, v).labels, seg.labels);
  expectNoIodError(path);
}

TEST(SegmentFiles, AMultiFrameSeriesKeepsNoPerSliceInstances) {
  // The frames of one enhanced file are one instance: a SEG references the series only.
  const std::string file = std::string(VOXRAY_DATA_DIR) + "/dicom/pydicom-data/emri_small.dcm";
  ASSERT_TRUE(fs::exists(file)) << file << " is missing (see /work/shared/data)";
  const Volume v = importDicom(file);
  EXPECT_GT(v.dims.z, 1);
  EXPECT_TRUE(v.study.sliceSopInstanceUids.empty());
  EXPECT_FALSE(v.study.sopClassUid.empty());
}

}  // namespace
}  // namespace voxray
