#pragma once
// Test NIfTI files written with the NIfTI C library's own writer (libnifti2), so the headers
// hold exactly the sform, qform, scaling and types a test asks for.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray::test {

struct NiftiSpec {
  std::vector<int64_t> dims{4, 3, 2};  // nx, ny, nz[, nt ...]
  int datatype = 4;                    // DT_INT16
  std::vector<double> values;          // dims product values (converted to DATATYPE); empty: index
  bool nifti2 = false;
  int sformCode = 0, qformCode = 0;
  double sform[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};  // rows of srow_x/y/z
  double quatern[3] = {0, 0, 0};                                    // b, c, d
  double qoffset[3] = {0, 0, 0};
  double qfac = 1.0;
  double pixdim[3] = {1, 1, 1};
  double sclSlope = 0.0, sclInter = 0.0;
  int xyzUnits = 2;                 // NIFTI_UNITS_MM
  std::string descrip, intentName;  // free text, up to 79 and 15 characters
  int intentCode = 0;
};

// Writes SPEC to PATH (.nii or .nii.gz). Throws std::runtime_error when the library cannot.
void writeNifti(const std::string& path, const NiftiSpec& spec);

}  // namespace voxray::test
