// SUVbw after the QIBA vendor-neutral pseudo-code: the dose is decayed from the injection to
// the scan's start (Decay Correction START) or used as injected (ADMIN: the images are
// already decay-corrected to the injection). DICOM dates and times are parsed by DCMTK.
#include "voxray/io/suv.h"

#include <chrono>
#include <cmath>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcvrda.h>
#include <dcmtk/dcmdata/dcvrdt.h>
#include <dcmtk/dcmdata/dcvrtm.h>

#include "day_number.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

constexpr double kSecondsPerDay = 86400.0;

[[noreturn]] void refuse(const std::string& why) {
  throw inputError("SUVbw cannot be computed: " + why + "; values are shown in Bq/mL");
}

std::string missing(const char* name, const char* tag) {
  return std::string(name) + " " + tag + " is missing";
}

// Seconds since 1970 of DA DATE and TM TIME (no time zone); nothing when either does not parse.
std::optional<double> dateTimeSeconds(const std::string& date, const std::string& time) {
  OFDate d;
  OFTime t;
  if (date.empty() || time.empty() || DcmDate::getOFDateFromString(date.c_str(), d).bad() ||
      DcmTime::getOFTimeFromString(time.c_str(), t).bad())
    return std::nullopt;
  return dicom::dayNumber(d) * kSecondsPerDay + t.getTimeInSeconds(false /*time zone*/);
}

std::optional<double> dateTimeSeconds(const std::string& dt) {
  OFDateTime v;
  if (dt.empty() || DcmDateTime::getOFDateTimeFromString(dt.c_str(), v).bad()) return std::nullopt;
  return dicom::dayNumber(v.getDate()) * kSecondsPerDay +
         v.getTime().getTimeInSeconds(false /*time zone*/);
}

// The scan's start: the series date and time, unless an image was acquired before it (a
// series re-made after the scan, QIBA's case): then GE's private scan DateTime when the
// file has one, else the earliest acquisition (which on GE may be a later bed's).
double scanStart(const PetSuvAttributes& a) {
  if (a.seriesDate.empty()) refuse(missing("Series Date", "(0008,0021)"));
  if (a.seriesTime.empty()) refuse(missing("Series Time", "(0008,0031)"));
  const auto series = dateTimeSeconds(a.seriesDate, a.seriesTime);
  if (!series)
    refuse("Series Date/Time '" + a.seriesDate + " " + a.seriesTime + "' is not a DICOM date/time");
  const auto acquired = dateTimeSeconds(
      a.acquisitionDate.empty() ? a.seriesDate : a.acquisitionDate, a.acquisitionTime);
  if (!acquired || *acquired >= *series) return *series;
  if (const auto ge = dateTimeSeconds(a.geScanDateTime)) return *ge;
  return *acquired;
}

double injection(const PetSuvAttributes& a, double scan) {
  if (!a.injectionDateTime.empty()) {
    if (auto t = dateTimeSeconds(a.injectionDateTime)) return *t;
    refuse("Radiopharmaceutical Start DateTime (0018,1078) '" + a.injectionDateTime +
           "' is not a DICOM date-time");
  }
  if (a.injectionTime.empty())
    refuse(missing("Radiopharmaceutical Start Time", "(0018,1072)") +
           " (nor Start DateTime (0018,1078)) in the Radiopharmaceutical Information Sequence");
  auto t = dateTimeSeconds(a.seriesDate, a.injectionTime);
  if (!t)
    refuse("Radiopharmaceutical Start Time (0018,1072) '" + a.injectionTime +
           "' is not a DICOM time");
  // Only a time: on the scan's day, or the day before when that puts it after the scan.
  return *t > scan ? *t - kSecondsPerDay : *t;
}

}  // namespace

double suvDecaySeconds(const PetSuvAttributes& a) {
  if (a.units.empty()) refuse(missing("Units", "(0054,1001)"));
  if (a.units != "BQML")
    refuse("Units (0054,1001) is '" + a.units + "', not BQML (activity concentration)");
  if (a.decayCorrection.empty()) refuse(missing("Decay Correction", "(0054,1102)"));
  if (a.decayCorrection == "ADMIN") return 0.0;
  if (a.decayCorrection != "START")
    refuse("Decay Correction (0054,1102) is '" + a.decayCorrection + "', not START or ADMIN");
  const double scan = scanStart(a);
  const double seconds = scan - injection(a, scan);
  // Days are possible (zirconium-89 is imaged up to a week after the injection).
  if (seconds < 0) refuse("the radiopharmaceutical start is after the scan's start");
  return seconds;
}

SuvScale suvbwScale(const PetSuvAttributes& a) {
  const double decay = suvDecaySeconds(a);
  if (!a.injectedDoseBq)
    refuse(missing("Radionuclide Total Dose", "(0018,1074)") + " or not positive");
  if (!a.halfLifeS && a.decayCorrection != "ADMIN")
    refuse(missing("Radionuclide Half Life", "(0018,1075)") + " or not positive");
  if (!a.weightKg) refuse(missing("Patient's Weight", "(0010,1030)") + " or not positive");
  const double dose =
      decay > 0 ? *a.injectedDoseBq * std::exp2(-decay / *a.halfLifeS) : *a.injectedDoseBq;
  SuvScale s;
  s.factor = *a.weightKg * 1000.0 / dose;  // kg -> g: SUV is (Bq/mL) / (Bq/g)
  return s;
}

}  // namespace voxray
