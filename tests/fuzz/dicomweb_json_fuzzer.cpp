// Fuzzes the reading of QIDO-RS answers (io/pacs/src/dicom_json.h): whatever JSON a node
// sends, each object becomes a match without an exception (a value of the wrong JSON type
// reads as absent), and every count it reports is a whole number >= 0.
#include <cstddef>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "dicom_json.h"

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void read(const nlohmann::json& object) {
  const voxray::PacsMatch m = voxray::pacs::toMatch(object);
  check(m.numberOfSeries >= 0 && m.numberOfInstances >= 0 && m.seriesNumber >= 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto answer = nlohmann::json::parse(data, data + size, nullptr, false);
  if (answer.is_object()) read(answer);
  if (answer.is_array())
    for (const auto& o : answer)
      if (o.is_object()) read(o);
  return 0;
}
