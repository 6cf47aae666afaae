#include "dicom_json.h"

#include "match_values.h"

namespace voxray::pacs {
namespace {

using nlohmann::json;

// The first value of a DICOM JSON attribute as text (PN: its alphabetic form); empty when
// the attribute, its Value array or a value of a usable type is missing.
std::string value(const json& object, const char* tag) {
  auto it = object.find(tag);
  if (it == object.end() || !it->is_object()) return {};
  auto list = it->find("Value");
  if (list == it->end() || !list->is_array() || list->empty()) return {};
  const json& v = list->front();
  if (v.is_object()) {
    auto name = v.find("Alphabetic");
    return name != v.end() && name->is_string() ? name->get<std::string>() : std::string();
  }
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return v.dump();  // as sent: countValue takes whole numbers only
  return {};
}

// Every string value of a multi-valued attribute, joined by backslashes as DICOM does.
std::string values(const json& object, const char* tag) {
  std::string out;
  auto it = object.find(tag);
  if (it == object.end() || !it->is_object()) return out;
  auto list = it->find("Value");
  if (list == it->end() || !list->is_array()) return out;
  for (const auto& v : *list)
    if (v.is_string()) out.append(out.empty() ? "" : "\\").append(v.get<std::string>());
  return out;
}

int number(const json& object, const char* tag) { return countValue(value(object, tag)); }

}  // namespace

PacsMatch toMatch(const json& o) {
  PacsMatch m;
  m.patientName = value(o, "00100010");
  m.patientId = value(o, "00100020");
  m.studyInstanceUid = value(o, "0020000D");
  m.studyDate = value(o, "00080020");
  m.studyDescription = value(o, "00081030");
  m.accessionNumber = value(o, "00080050");
  m.modalities = o.contains("00080061") ? values(o, "00080061") : value(o, "00080060");
  m.numberOfSeries = number(o, "00201206");
  m.numberOfInstances = o.contains("00201208") ? number(o, "00201208") : number(o, "00201209");
  m.seriesInstanceUid = value(o, "0020000E");
  m.seriesDescription = value(o, "0008103E");
  m.seriesNumber = number(o, "00200011");
  return m;
}

}  // namespace voxray::pacs
