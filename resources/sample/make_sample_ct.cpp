// voxray-make-sample: writes the workstation's embedded sample CT from the shared Philips
// head-phantom series (Chris Rorden's dcm_qa data, BSD-2-Clause): the series' volume
// averaged over 2 x 2 pixels (0.9 mm in plane; the 5 mm slices as they are), stored as
// little-endian int16 compressed with zlib, and a JSON file with its geometry, the window
// and where it came from. Run by resources/sample/make-sample-ct.sh; never at build time.
#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

using namespace voxray;

namespace {

constexpr double kBoneWindow[2] = {1500.0, 300.0};  // width, level in HU

Volume halveInPlane(const Volume& v) {
  Volume out = v;
  out.dims = {v.dims.x / 2, v.dims.y / 2, v.dims.z};
  out.spacingMm = {v.spacingMm.x * 2, v.spacingMm.y * 2, v.spacingMm.z};
  // The centre of the first 2 x 2 block.
  out.originMm =
      v.originMm + v.direction[0] * (0.5 * v.spacingMm.x) + v.direction[1] * (0.5 * v.spacingMm.y);
  out.voxels.assign(out.voxelCount(), 0);
  for (int z = 0; z < out.dims.z; ++z)
    for (int y = 0; y < out.dims.y; ++y)
      for (int x = 0; x < out.dims.x; ++x) {
        int sum = v.at(2 * x, 2 * y, z) + v.at(2 * x + 1, 2 * y, z) + v.at(2 * x, 2 * y + 1, z) +
                  v.at(2 * x + 1, 2 * y + 1, z);
        // Round half away from zero, as the test that checks this file does.
        out.voxels[out.index(x, y, z)] = int16_t(sum >= 0 ? (sum + 2) / 4 : -((-sum + 2) / 4));
      }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: voxray-make-sample PHILIPS_SERIES_FOLDER OUT.json OUT.i16.zlib\n";
    return 2;
  }
  try {
    Volume src = importDicom(argv[1]);
    Volume v = halveInPlane(src);
    std::vector<uint8_t> le(v.byteSize());
    for (size_t i = 0; i < v.voxels.size(); ++i) {
      le[2 * i] = uint8_t(uint16_t(v.voxels[i]) & 0xff);
      le[2 * i + 1] = uint8_t(uint16_t(v.voxels[i]) >> 8);
    }
    uLongf packedSize = compressBound(uLong(le.size()));
    std::vector<uint8_t> packed(packedSize);
    if (compress2(packed.data(), &packedSize, le.data(), uLong(le.size()), 9) != Z_OK)
      throw std::runtime_error("zlib could not compress the volume");
    std::ofstream(argv[3], std::ios::binary)
        .write(reinterpret_cast<const char*>(packed.data()), std::streamsize(packedSize));
    nlohmann::ordered_json j;
    j["what"] =
        "CT of a plastic head phantom (Philips scanner, series 201, 28 slices of 5 mm), "
        "averaged over 2 x 2 pixels";
    j["source"] =
        "Chris Rorden's DICOM validation data (dcm_qa), BSD-2-Clause, (c) 2019 Chris Rorden; "
        "the shared test data's dicom/ct-philips-phantom";
    j["dims"] = {v.dims.x, v.dims.y, v.dims.z};
    j["spacingMm"] = {v.spacingMm.x, v.spacingMm.y, v.spacingMm.z};
    j["originMm"] = {v.originMm.x, v.originMm.y, v.originMm.z};
    for (int c = 0; c < 3; ++c)
      j["direction"].push_back({v.direction[c].x, v.direction[c].y, v.direction[c].z});
    j["slope"] = v.slope;
    j["intercept"] = v.intercept;
    j["modality"] = v.modality;
    // A bone window: the phantom is a plastic skull filled with air, so the series' own
    // brain window (80/40) shows white bone on black and nothing else.
    j["window"] = {kBoneWindow[0], kBoneWindow[1]};
    j["windowExplanation"] = "Bone";
    j["bytes"] = le.size();
    std::ofstream(argv[2]) << j.dump(2) << "\n";
    std::printf("%dx%dx%d, %zu bytes -> %lu compressed\n", v.dims.x, v.dims.y, v.dims.z, le.size(),
                packedSize);
  } catch (const std::exception& e) {
    std::cerr << "voxray-make-sample: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
