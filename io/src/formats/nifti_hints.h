#pragma once
// What a NIfTI header says about its values. NIfTI has no modality field: a CT converted
// to NIfTI loses "CT", and its HU open with a look from the histogram and an "HU"-less
// panel. The free-text descrip and intent_name often keep it ("CT head", "HU", "PET SUV");
// read conservatively: a whole word, and nothing that contradicts it (a PET/CT's PET image
// says "CT" too).
#include <string>

namespace voxray::formats {

struct ValueHint {
  std::string modality;  // "CT", "PT", "MR"; empty: nothing said
  std::string unit;      // "HU", "SUV"; empty: nothing said (the reader's own stays)
};

// From the header's descrip (80 characters) and intent_name (16). NIfTI-1's intent codes
// are statistics (t, z, p ...), labels and vectors: none names a modality or HU.
ValueHint niftiValueHint(const std::string& descrip, const std::string& intentName);

}  // namespace voxray::formats
