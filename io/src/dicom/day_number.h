#pragma once
// Days since 1970-01-01 of a DICOM date (its calendar date): one copy for the SUV decay
// (suv.cpp) and the PET phantom's times (phantom_series.cpp).
#include <chrono>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/ofstd/ofdate.h>

namespace voxray::dicom {

inline double dayNumber(const OFDate& d) {
  using namespace std::chrono;
  return double(
      sys_days(year_month_day(year(int(d.getYear())), month(d.getMonth()), day(d.getDay())))
          .time_since_epoch()
          .count());
}

}  // namespace voxray::dicom
