// A QIDO-RS match read from DICOM JSON: the usual answer, and values of the wrong JSON type
// (a Value that is no array, a name that is a number, a count of 1.5e300), which read as
// absent instead of throwing nlohmann's type_error (an "internal error" in voxray-cli).
#include <gtest/gtest.h>

#include "dicom_json.h"

namespace voxray::pacs {
namespace {

using nlohmann::json;

TEST(DicomJson, AStudyMatchReadsItsValues) {
  const PacsMatch m = toMatch(json::parse(R"({
    "00100010": {"vr": "PN", "Value": [{"Alphabetic": "HEAD"}]},
    "0020000D": {"vr": "UI", "Value": ["1.2.3"]},
    "00080061": {"vr": "CS", "Value": ["CT", "OT"]},
    "00201206": {"vr": "IS", "Value": [3]},
    "00201208": {"vr": "IS", "Value": ["35"]}})"));
  EXPECT_EQ(m.patientName, "HEAD");
  EXPECT_EQ(m.studyInstanceUid, "1.2.3");
  EXPECT_EQ(m.modalities, "CT\\OT");
  EXPECT_EQ(m.numberOfSeries, 3);
  EXPECT_EQ(m.numberOfInstances, 35);
}

TEST(DicomJson, ValuesOfTheWrongTypeReadAsAbsent) {
  const PacsMatch m = toMatch(json::parse(R"({
    "00100010": {"vr": "PN", "Value": [{"Alphabetic": 7}]},
    "00100020": {"vr": "LO", "Value": 5},
    "0020000D": "1.2.3",
    "00080061": {"vr": "CS", "Value": "CT"},
    "00201206": {"vr": "IS", "Value": [1.5e300]},
    "00200011": {"vr": "IS", "Value": [[2]]}})"));
  EXPECT_EQ(m.patientName, "");
  EXPECT_EQ(m.patientId, "");
  EXPECT_EQ(m.studyInstanceUid, "");
  EXPECT_EQ(m.modalities, "");
  EXPECT_EQ(m.numberOfSeries, 0);
  EXPECT_EQ(m.seriesNumber, 0);
}

}  // namespace
}  // namespace voxray::pacs
