// voxray-cli make-phantom: DICOM series of known phantoms (phantom_series.h) for trying and
// testing PET SUV and 4D: what they should measure is printed, from the phantom's numbers.
#include <cmath>
#include <iostream>

#include "commands.h"
#include "voxray/io/error.h"
#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/phantom_series.h"
#endif

namespace voxray::cli {

namespace {

struct PhantomOptions {
  std::string kind, dir;
  std::string decay = "START", seriesTime, acquisitionTime, injectionTime, injectionDateTime,
              geScanDateTime, timing = "temporal";
  std::vector<std::string> omit;
  std::vector<int> dims;
  int phases = 10, timePoints = 3;
  double weightKg = 0;
};

int runMakePhantom(const PhantomOptions& o) {
#ifdef VOXRAY_HAS_DICOM
  if (!o.dims.empty() && o.dims.size() != 3)
    throw inputError("--dims: give X,Y,Z (voxels along each axis)");
  if (o.kind == "pet-sphere") {
    PetSpherePhantom p;
    p.decayCorrection = o.decay;
    if (!o.seriesTime.empty()) p.seriesTime = p.acquisitionTime = o.seriesTime;
    if (!o.acquisitionTime.empty()) p.acquisitionTime = o.acquisitionTime;
    p.geScanDateTime = o.geScanDateTime;
    if (!o.injectionTime.empty()) p.injectionTime = o.injectionTime;
    p.injectionDateTime = o.injectionDateTime;
    if (o.weightKg > 0) p.weightKg = o.weightKg;
    p.omit.insert(o.omit.begin(), o.omit.end());
    if (!o.dims.empty()) p.dims = {o.dims[0], o.dims[1], o.dims[2]};
    writePetSpherePhantom(o.dir, p);
    std::cout << "wrote " << p.dims.z << " PET images to " << o.dir << "\n"
              << "sphere radius " << p.radiusMm << " mm, " << p.insideBqml
              << " Bq/mL inside, SUVbw " << petSphereSuv(p) << "\n";
    return 0;
  }
  if (o.kind == "mosaic") {
    MosaicPhantom p;
    p.timePoints = o.timePoints;
    if (!o.dims.empty()) p.dims = {o.dims[0], o.dims[1], o.dims[2]};
    writeMosaicPhantom(o.dir, p);
    const int across = int(std::ceil(std::sqrt(double(p.dims.z)) - 1e-9));
    std::cout << "wrote " << p.timePoints << " Siemens mosaic MR images to " << o.dir << "\n"
              << p.dims.z << " slices of " << p.dims.x << "x" << p.dims.y << " tiled " << across
              << " x " << across << " in " << across * p.dims.x << "x" << across * p.dims.y
              << " pixels; sphere radius " << p.radiusMm << " mm\n";
    return 0;
  }
  BeatingSpherePhantom p;
  p.phases = o.phases;
  p.timing = o.timing;
  if (!o.dims.empty()) p.dims = {o.dims[0], o.dims[1], o.dims[2]};
  writeBeatingSpherePhantom(o.dir, p);
  std::cout << "wrote " << p.phases << " phases of " << p.dims.z << " CT images to " << o.dir
            << "\nsphere radius per phase (mm):";
  for (int t = 0; t < p.phases; ++t) std::cout << " " << p.radiusAt(t);
  std::cout << "\n";
  return 0;
#else
  (void)o;
  throw inputError("make-phantom: this build of Voxray cannot write DICOM (built without DCMTK)");
#endif
}

}  // namespace

Run addMakePhantomCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "make-phantom",
      "Write a DICOM phantom series: pet-sphere (PET of known SUV), beating-sphere (4D CT) or "
      "mosaic (Siemens mosaic fMRI, 4D)");
  auto o = std::make_shared<PhantomOptions>();
  cmd->add_option("kind", o->kind, "pet-sphere, beating-sphere or mosaic")
      ->required()
      ->check(CLI::IsMember({"pet-sphere", "beating-sphere", "mosaic"}));
  cmd->add_option("dir", o->dir, "a new or empty folder for the files")->required();
  cmd->add_option("--decay", o->decay, "pet-sphere: Decay Correction, START or ADMIN")
      ->check(CLI::IsMember({"START", "ADMIN", "NONE"}));
  cmd->add_option("--series-time", o->seriesTime, "pet-sphere: Series Time (HHMMSS)");
  cmd->add_option("--acquisition-time", o->acquisitionTime,
                  "pet-sphere: every image's Acquisition Time (HHMMSS); default the series time");
  cmd->add_option("--ge-scan-datetime", o->geScanDateTime,
                  "pet-sphere: GE's private scan DateTime (0009,100D) (YYYYMMDDHHMMSS)");
  cmd->add_option("--injection-time", o->injectionTime,
                  "pet-sphere: Radiopharmaceutical Start Time (HHMMSS)");
  cmd->add_option("--injection-datetime", o->injectionDateTime,
                  "pet-sphere: Radiopharmaceutical Start DateTime (YYYYMMDDHHMMSS)");
  cmd->add_option("--weight", o->weightKg, "pet-sphere: Patient's Weight in kg");
  cmd->add_option("--omit", o->omit,
                  "pet-sphere: leave out an attribute SUV needs (PatientWeight, Units, "
                  "DecayCorrection, RadionuclideTotalDose, RadionuclideHalfLife, "
                  "RadiopharmaceuticalStartTime, SeriesTime)");
  cmd->add_option("--dims", o->dims, "voxels X,Y,Z")->delimiter(',');
  cmd->add_option("--phases", o->phases, "beating-sphere: phases (time points)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--time-points", o->timePoints, "mosaic: volumes (one mosaic image each)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--timing", o->timing,
                  "beating-sphere: how phases are marked: temporal (Temporal Position "
                  "Identifier), trigger (Trigger Time) or repeated (positions repeated)")
      ->check(CLI::IsMember({"temporal", "trigger", "repeated"}));
  return [o] { return runMakePhantom(*o); };
}

}  // namespace voxray::cli
