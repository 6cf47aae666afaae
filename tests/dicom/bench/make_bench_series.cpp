// Writes the benchmark series: 512x512x500 CT made from the Visible Human pelvis (150
// slices, repeated along z), once uncompressed and once JPEG lossless, as single-slice
// files with shuffled names. Usage: voxray_make_bench_series [OUT_DIR=/tmp/voxray-bench]
// Output must stay outside the repository and the shared data.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dctk.h>
#include <dcmtk/dcmjpeg/djencode.h>
#include <dcmtk/dcmjpeg/djrplol.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace {

constexpr int kSlices = 500;

bool writeSlice(const voxray::Volume& src, int k, const std::string& path, E_TransferSyntax xfer,
                const std::string& seriesUid) {
  const int n = src.dims.x * src.dims.y;
  const int16_t* pixels = src.voxels.data() + size_t(k % src.dims.z) * n;
  DcmFileFormat file;
  DcmDataset* ds = file.getDataset();
  char uid[100];
  ds->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
  ds->putAndInsertString(DCM_SOPInstanceUID,
                         dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
  ds->putAndInsertString(DCM_SeriesInstanceUID, seriesUid.c_str());
  ds->putAndInsertString(DCM_StudyInstanceUID, seriesUid.c_str());
  ds->putAndInsertString(DCM_Modality, "CT");
  ds->putAndInsertString(DCM_SeriesNumber, "1");
  ds->putAndInsertString(DCM_InstanceNumber, std::to_string(k + 1).c_str());
  ds->putAndInsertString(DCM_SeriesDescription, "Voxray benchmark 512x512x500");
  std::string pos = "0\\0\\" + std::to_string(k);
  ds->putAndInsertString(DCM_ImagePositionPatient, pos.c_str());
  ds->putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
  ds->putAndInsertString(DCM_PixelSpacing, "0.7\\0.7");
  ds->putAndInsertString(DCM_SliceThickness, "1");
  ds->putAndInsertUint16(DCM_Rows, Uint16(src.dims.y));
  ds->putAndInsertUint16(DCM_Columns, Uint16(src.dims.x));
  ds->putAndInsertUint16(DCM_SamplesPerPixel, 1);
  ds->putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
  ds->putAndInsertUint16(DCM_BitsAllocated, 16);
  ds->putAndInsertUint16(DCM_BitsStored, 16);
  ds->putAndInsertUint16(DCM_HighBit, 15);
  ds->putAndInsertUint16(DCM_PixelRepresentation, 1);
  ds->putAndInsertString(DCM_RescaleIntercept, std::to_string(src.intercept).c_str());
  ds->putAndInsertString(DCM_RescaleSlope, std::to_string(src.slope).c_str());
  ds->putAndInsertUint16Array(DCM_PixelData, reinterpret_cast<const Uint16*>(pixels), unsigned(n));
  if (xfer != EXS_LittleEndianExplicit) {
    DJ_RPLossless params;
    if (ds->chooseRepresentation(xfer, &params).bad() || !ds->canWriteXfer(xfer)) return false;
  }
  return file.saveFile(path.c_str(), xfer).good();
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const fs::path out = argc > 1 ? argv[1] : "/tmp/voxray-bench";
  const fs::path pelvis = fs::path(VOXRAY_DATA_DIR) / "dicom/ct-visible-human-pelvis";
  try {
    voxray::Volume src = voxray::importDicom(pelvis.string());
    DJEncoderRegistration::registerCodecs();
    std::vector<int> names(kSlices);
    for (int k = 0; k < kSlices; ++k) names[k] = k;
    std::shuffle(names.begin(), names.end(), std::mt19937(42));  // names not in z order
    struct Variant {
      const char* dir;
      E_TransferSyntax xfer;
    } variants[] = {{"uncompressed", EXS_LittleEndianExplicit},
                    {"jpeg-lossless", EXS_JPEGProcess14SV1}};
    for (auto& v : variants) {
      fs::create_directories(out / v.dir);
      char uid[100];
      std::string series = dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT);
      for (int k = 0; k < kSlices; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "slice%04d.dcm", names[k]);
        if (!writeSlice(src, k, (out / v.dir / name).string(), v.xfer, series)) {
          std::fprintf(stderr, "cannot write %s\n", (out / v.dir / name).c_str());
          return 1;
        }
      }
      std::printf("wrote %d slices to %s\n", kSlices, (out / v.dir).c_str());
    }
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
