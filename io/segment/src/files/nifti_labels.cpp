// NIfTI label maps through the NIfTI C library (libnifti2), as io's NIfTI reader.
#include <nifti2_io.h>

#include <cmath>
#include <memory>

#include "formats.h"
#include "voxray/io/error.h"

namespace voxray::segfiles {
namespace {

struct NiftiFree {
  void operator()(nifti_image* n) const { nifti_image_free(n); }
};
using NiftiPtr = std::unique_ptr<nifti_image, NiftiFree>;

// NIfTI's world is RAS: LPS x and y change sign.
constexpr double kFlip[3] = {-1.0, -1.0, 1.0};

nifti_dmat44 rasAffine(const VoxelGrid& g) {
  nifti_dmat44 a{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a.m[r][c] = kFlip[r] * g.direction[c][r] * g.spacingMm[c];
    a.m[r][3] = kFlip[r] * g.originMm[r];
  }
  a.m[3][3] = 1.0;
  return a;
}

VoxelGrid gridOfAffine(const nifti_dmat44& a, const glm::ivec3& dims) {
  VoxelGrid g;
  g.dims = dims;
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 axis{kFlip[0] * a.m[0][c], kFlip[1] * a.m[1][c], kFlip[2] * a.m[2][c]};
    g.spacingMm[c] = glm::length(axis);
    g.direction[c] = g.spacingMm[c] > 0 ? axis / g.spacingMm[c] : glm::dvec3(0.0);
  }
  g.originMm = {kFlip[0] * a.m[0][3], kFlip[1] * a.m[1][3], kFlip[2] * a.m[2][3]};
  return g;
}

template <typename T>
void copyNiftiLabels(const nifti_image& n, double slope, double inter, LabelFile& out,
                     const std::string& path) {
  const T* v = static_cast<const T*>(n.data);
  for (size_t i = 0; i < out.labels.size(); ++i) {
    const double value = double(v[i]) * slope + inter;
    if (value != 0.0 && (value < 0 || value > 255 || value != std::floor(value)))
      throw inputError(labelValueProblem(value, path));
    out.labels[i] = uint8_t(value);
  }
}

}  // namespace

void writeNifti(const std::string& temporary, const Segmentation& seg) {
  nifti_set_debug_level(0);
  const VoxelGrid& g = seg.grid;
  const int64_t dims[8] = {3, g.dims.x, g.dims.y, g.dims.z, 1, 1, 1, 1};
  NiftiPtr n(nifti_make_new_nim(dims, DT_UINT8, 0));
  if (!n) throw outputError(temporary + ": the NIfTI library could not make a header");
  if (nifti_set_filenames(n.get(), temporary.c_str(), 0, 1) != 0)
    throw outputError(temporary + ": the NIfTI library refused the file name");
  n->nifti_type = NIFTI_FTYPE_NIFTI1_1;
  n->xyz_units = NIFTI_UNITS_MM;
  n->intent_code = NIFTI_INTENT_LABEL;
  std::snprintf(n->descrip, sizeof n->descrip, "Voxray segmentation");
  // Both transforms: tools that read only the qform (older FSL) place it too.
  const nifti_dmat44 a = rasAffine(g);
  n->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  n->sto_xyz = a;
  n->sto_ijk = nifti_dmat44_inverse(a);
  double qfac = 1.0, dx = 0, dy = 0, dz = 0;
  nifti_dmat44_to_quatern(a, &n->quatern_b, &n->quatern_c, &n->quatern_d, &n->qoffset_x,
                          &n->qoffset_y, &n->qoffset_z, &dx, &dy, &dz, &qfac);
  n->qfac = qfac;
  n->qform_code = NIFTI_XFORM_SCANNER_ANAT;
  n->dx = n->pixdim[1] = g.spacingMm.x;
  n->dy = n->pixdim[2] = g.spacingMm.y;
  n->dz = n->pixdim[3] = g.spacingMm.z;
  n->qto_xyz = nifti_quatern_to_dmat44(n->quatern_b, n->quatern_c, n->quatern_d, n->qoffset_x,
                                       n->qoffset_y, n->qoffset_z, n->dx, n->dy, n->dz, n->qfac);
  // The library writes from data and frees it with the image: lend it ours, take it back.
  n->data = const_cast<uint8_t*>(seg.labels.data());
  nifti_image_write(n.get());
  n->data = nullptr;
}

LabelFile readNifti(const std::string& path) {
  nifti_set_debug_level(0);
  NiftiPtr n(nifti_image_read(path.c_str(), 1));
  if (!n || !n->data)
    throw inputError(path + ": is not a NIfTI file that can be read (damaged or truncated?)");
  if (n->nx < 1 || n->ny < 1 || n->nz < 1 || n->nt > 1 || n->nu > 1)
    throw inputError(path + ": is not a 3D label map (it has " + std::to_string(n->ndim) +
                     " dimensions of data); a label map has one value per voxel");
  LabelFile out;
  const nifti_dmat44& a = n->sform_code > 0 ? n->sto_xyz : n->qto_xyz;
  out.grid = gridOfAffine(a, glm::ivec3(int(n->nx), int(n->ny), int(n->nz)));
  out.labels.resize(out.grid.voxelCount());
  const double slope = n->scl_slope != 0.0 && std::isfinite(n->scl_slope) ? n->scl_slope : 1.0;
  const double inter = std::isfinite(n->scl_inter) ? n->scl_inter : 0.0;
  switch (n->datatype) {
    case DT_UINT8:
      copyNiftiLabels<uint8_t>(*n, slope, inter, out, path);
      break;
    case DT_INT8:
      copyNiftiLabels<int8_t>(*n, slope, inter, out, path);
      break;
    case DT_INT16:
      copyNiftiLabels<int16_t>(*n, slope, inter, out, path);
      break;
    case DT_UINT16:
      copyNiftiLabels<uint16_t>(*n, slope, inter, out, path);
      break;
    case DT_INT32:
      copyNiftiLabels<int32_t>(*n, slope, inter, out, path);
      break;
    case DT_UINT32:
      copyNiftiLabels<uint32_t>(*n, slope, inter, out, path);
      break;
    case DT_FLOAT32:
      copyNiftiLabels<float>(*n, slope, inter, out, path);
      break;
    case DT_FLOAT64:
      copyNiftiLabels<double>(*n, slope, inter, out, path);
      break;
    default:
      throw inputError(path + ": holds " + nifti_datatype_string(n->datatype) +
                       " values; a label map holds whole numbers 0 to 255");
  }
  return out;
}

}  // namespace voxray::segfiles
