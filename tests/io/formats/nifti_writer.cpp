#include "nifti_writer.h"

#include <nifti2_io.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace voxray::test {
namespace {

template <class T>
void fill(void* data, const std::vector<double>& values) {
  auto* out = static_cast<T*>(data);
  for (size_t i = 0; i < values.size(); ++i) out[i] = T(values[i]);
}

void fillData(nifti_image* nim, const std::vector<double>& values) {
  using Fill = void (*)(void*, const std::vector<double>&);
  static const std::pair<int, Fill> fills[] = {
      {DT_UINT8, fill<uint8_t>}, {DT_INT8, fill<int8_t>},     {DT_UINT16, fill<uint16_t>},
      {DT_INT16, fill<int16_t>}, {DT_UINT32, fill<uint32_t>}, {DT_INT32, fill<int32_t>},
      {DT_FLOAT32, fill<float>}, {DT_FLOAT64, fill<double>}};
  for (const auto& [type, f] : fills)
    if (type == nim->datatype) return f(nim->data, values);
  throw std::runtime_error("writeNifti: no test filler for this datatype");
}

}  // namespace

void writeNifti(const std::string& path, const NiftiSpec& spec) {
  int64_t dims[8] = {int64_t(spec.dims.size()), 1, 1, 1, 1, 1, 1, 1};
  int64_t count = 1;
  for (size_t a = 0; a < spec.dims.size(); ++a) {
    dims[a + 1] = spec.dims[a];
    count *= spec.dims[a];
  }
  nifti_image* nim = nifti_make_new_nim(dims, spec.datatype, 1);
  if (!nim) throw std::runtime_error("writeNifti: nifti_make_new_nim failed");
  std::vector<double> values = spec.values;
  if (values.empty())
    for (int64_t i = 0; i < count; ++i) values.push_back(double(i));
  if (int64_t(values.size()) != count) throw std::runtime_error("writeNifti: value count");
  fillData(nim, values);
  nim->nifti_type = spec.nifti2 ? NIFTI_FTYPE_NIFTI2_1 : NIFTI_FTYPE_NIFTI1_1;
  nim->sform_code = spec.sformCode;
  nim->qform_code = spec.qformCode;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) nim->sto_xyz.m[r][c] = spec.sform[r][c];
  nim->quatern_b = spec.quatern[0];
  nim->quatern_c = spec.quatern[1];
  nim->quatern_d = spec.quatern[2];
  nim->qoffset_x = spec.qoffset[0];
  nim->qoffset_y = spec.qoffset[1];
  nim->qoffset_z = spec.qoffset[2];
  nim->qfac = spec.qfac;
  nim->dx = nim->pixdim[1] = spec.pixdim[0];
  nim->dy = nim->pixdim[2] = spec.pixdim[1];
  nim->dz = nim->pixdim[3] = spec.pixdim[2];
  nim->scl_slope = spec.sclSlope;
  nim->scl_inter = spec.sclInter;
  nim->xyz_units = spec.xyzUnits;
  std::snprintf(nim->descrip, sizeof nim->descrip, "%s", spec.descrip.c_str());
  std::snprintf(nim->intent_name, sizeof nim->intent_name, "%s", spec.intentName.c_str());
  nim->intent_code = spec.intentCode;
  if (nifti_set_filenames(nim, path.c_str(), 0, 1) != 0) {
    nifti_image_free(nim);
    throw std::runtime_error("writeNifti: bad file name " + path);
  }
  nifti_image_write(nim);
  nifti_image_free(nim);
  if (!std::filesystem::exists(path)) throw std::runtime_error("writeNifti: nothing written");
}

}  // namespace voxray::test
