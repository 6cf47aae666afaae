// The patient and study corner text: what it says, and that a volume without a study (raw
// data, the phantom) shows none.
#include <gtest/gtest.h>

#include "study_text.h"

using namespace voxray;

TEST(StudyText, PersonNamesReadFamilyCommaGiven) {
  EXPECT_EQ(displayPersonName("DOE^JANE"), "DOE, JANE");
  EXPECT_EQ(displayPersonName("Doe^Jane^Q^Dr"), "Doe, Jane Q");
  EXPECT_EQ(displayPersonName("HEAD"), "HEAD");
  // Only the alphabetic form of a name with ideographic and phonetic forms (PS3.5 6.2).
  EXPECT_EQ(displayPersonName("Yamada^Tarou=山田^太郎=やまだ^たろう"), "Yamada, Tarou");
  EXPECT_EQ(displayPersonName(""), "");
}

TEST(StudyText, DatesAreIsoAndOtherTextStaysAsItIs) {
  EXPECT_EQ(displayDate("20190501"), "2019-05-01");
  EXPECT_EQ(displayDate("20190501", "102233.500"), "2019-05-01 10:22");
  EXPECT_EQ(displayDate("20190501", "10"), "2019-05-01");  // too short a time: left out
  EXPECT_EQ(displayDate("2019.05.01"), "2019.05.01");      // old ACR-NEMA form, as it is
  EXPECT_EQ(displayDate(""), "");
}

TEST(StudyText, LinesLeaveOutEmptyFields) {
  StudyIdentity s;
  EXPECT_TRUE(studyTextLines(s).empty());  // raw data and the phantom: no text at all
  s.studyInstanceUid = "1.2.3";            // UIDs are not shown
  EXPECT_TRUE(studyTextLines(s).empty());
  s.patientName = "DOE^JANE";
  s.patientId = "1234567";
  s.patientBirthDate = "19700101";
  s.studyDate = "20190501";
  s.studyTime = "1022";
  s.studyDescription = "CT HEAD";
  s.accessionNumber = "A55";
  s.seriesNumber = 2;
  s.seriesDescription = "Axial 1mm";
  EXPECT_EQ(
      studyTextLines(s),
      (std::vector<std::string>{"DOE, JANE", "ID 1234567 · born 1970-01-01",
                                "2019-05-01 10:22 · CT HEAD", "Acc A55", "Series 2 · Axial 1mm"}));
  s.patientId.clear();
  s.studyDescription.clear();
  s.accessionNumber.clear();
  s.seriesNumber = 0;
  EXPECT_EQ(studyTextLines(s), (std::vector<std::string>{"DOE, JANE", "born 1970-01-01",
                                                         "2019-05-01 10:22", "Axial 1mm"}));
}
