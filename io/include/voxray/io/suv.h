#pragma once
// PET standardised uptake value, body-weight normalised (SUVbw), as the QIBA FDG-PET/CT
// profile's vendor-neutral SUV calculation defines it, from the DICOM PET attributes (PS3.3
// C.8.9.1 PET Series, C.8.9.2 PET Isotope). Dates and times are DICOM text (DA, TM, DT).
#include <optional>
#include <string>

#include "voxray/io/volume.h"

namespace voxray {

struct PetSuvAttributes {
  std::string units;                             // (0054,1001) Units: must be BQML
  std::string decayCorrection;                   // (0054,1102) START or ADMIN
  std::string seriesDate, seriesTime;            // (0008,0021), (0008,0031)
  std::string acquisitionDate, acquisitionTime;  // the series' earliest (0008,0022/0032)
  // In Radiopharmaceutical Information Sequence (0054,0016), its first item:
  std::string injectionTime;             // (0018,1072) Radiopharmaceutical Start Time
  std::string injectionDateTime;         // (0018,1078) Radiopharmaceutical Start DateTime
  std::optional<double> injectedDoseBq;  // (0018,1074) Radionuclide Total Dose
  std::optional<double> halfLifeS;       // (0018,1075) Radionuclide Half Life
  std::optional<double> weightKg;        // (0010,1030) Patient's Weight
  // GE's private scan start, (0009,xx0D) of creator GEMS_PETD_01 (DT): QIBA's scan time when
  // the series time is later than the acquisition (a series made after the scan).
  std::string geScanDateTime;
};

// The scale from Bq/mL to SUVbw. Throws Error (Input) naming the attribute that is missing or
// unusable (and saying the values stay in Bq/mL) when SUV cannot be computed.
SuvScale suvbwScale(const PetSuvAttributes& a);

// Seconds between the injection and the scan start that suvbwScale decays the dose over (0
// for ADMIN); throws as suvbwScale does.
double suvDecaySeconds(const PetSuvAttributes& a);

}  // namespace voxray
