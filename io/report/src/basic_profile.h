#pragma once
// PS3.15 Annex E, Table E.1-1: the attributes of the Basic Application Level Confidentiality
// Profile and what it does with each. The table lives in one place so that the export and
// its test (tests/report) read the same list.
#include <cstdint>
#include <vector>

namespace voxray::report {

enum class Action {
  Remove,  // X: the attribute goes
  Empty,   // Z: zero length (Type 2 attributes the IODs keep)
  Dummy,   // D: a dummy value of its VR (Type 1)
  NewUid,  // U: a new UID, the same for the same old UID within one export
};

struct ProfileAttribute {
  uint16_t group, element;
  Action action;
};

const std::vector<ProfileAttribute>& basicProfile();

}  // namespace voxray::report
