#include "voxray/io/sample_volume.h"

#include <zlib.h>

#include <bit>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"

extern "C" const unsigned char voxray_sample_ct_voxels[];
extern "C" const unsigned long long voxray_sample_ct_voxels_size;

namespace voxray {

const std::map<std::string, std::string_view>& embeddedSampleCtHeader();  // generated

namespace {

nlohmann::json header() {
  const auto& files = embeddedSampleCtHeader();
  return nlohmann::json::parse(files.at("head-phantom-ct.json"));
}

glm::dvec3 vec3(const nlohmann::json& a) { return {a.at(0), a.at(1), a.at(2)}; }

}  // namespace

Volume loadSampleCt() {
  try {
    const nlohmann::json h = header();
    Volume v;
    v.dims = {h.at("dims").at(0), h.at("dims").at(1), h.at("dims").at(2)};
    v.spacingMm = vec3(h.at("spacingMm"));
    v.originMm = vec3(h.at("originMm"));
    for (int c = 0; c < 3; ++c) v.direction[c] = vec3(h.at("direction").at(c));
    v.slope = h.at("slope");
    v.intercept = h.at("intercept");
    v.modality = h.at("modality");
    v.unit = "HU";
    v.sourceType = "i16";
    if (h.contains("window"))
      v.window = DisplayWindow{h["window"][0], h["window"][1], h.value("windowExplanation", ""),
                               "the sample's window"};
    v.study.studyDescription = "Sample: CT of a head phantom";
    v.voxels.resize(v.voxelCount());
    uLongf bytes = uLongf(v.byteSize());
    const int rc = uncompress(reinterpret_cast<Bytef*>(v.voxels.data()), &bytes,
                              voxray_sample_ct_voxels, uLong(voxray_sample_ct_voxels_size));
    if (rc != Z_OK || bytes != v.byteSize() || h.at("bytes") != v.byteSize())
      throw Error(Error::Kind::Internal, "zlib");
    // Stored little-endian; every machine Voxray builds for is little-endian, but say so.
    static_assert(std::endian::native == std::endian::little);
    return v;
  } catch (const std::exception&) {  // zlib, or a header nlohmann cannot read
    throw Error(Error::Kind::Internal,
                "the embedded sample CT is damaged (a broken build): rebuild Voxray, or open a "
                "file or the head phantom instead");
  }
}

std::string sampleCtAttribution() {
  return "Sample CT: a plastic head phantom scanned on a Philips CT, from Chris Rorden's DICOM "
         "validation data (dcm_qa), © 2019 Chris Rorden, BSD-2-Clause licence.";
}

}  // namespace voxray
