#include "basic_profile.h"

namespace voxray::report {

// Where Table E.1-1 gives a choice (X/Z, Z/D, X/Z/D, X/D, X/Z/U*), the action is the one the
// IODs Voxray reads allow: Type 2 attributes of CT/MR/PET images are emptied, Type 1 ones get
// a dummy, the rest go. Curves (50xx) and overlay data/comments (60xx,3000/4000) and every
// private attribute are removed by the export itself (anonymise.cpp).
const std::vector<ProfileAttribute>& basicProfile() {
  using A = Action;
  static const std::vector<ProfileAttribute> table = {
      {0x0008, 0x0012, A::Remove},  // Instance Creation Date
      {0x0008, 0x0013, A::Remove},  // Instance Creation Time
      {0x0008, 0x0014, A::NewUid},  // Instance Creator UID
      {0x0008, 0x0015, A::Remove},  // Instance Coercion DateTime
      {0x0008, 0x0018, A::NewUid},  // SOP Instance UID
      {0x0008, 0x0020, A::Empty},   // Study Date
      {0x0008, 0x0021, A::Remove},  // Series Date
      {0x0008, 0x0022, A::Remove},  // Acquisition Date
      {0x0008, 0x0023, A::Empty},   // Content Date
      {0x0008, 0x0024, A::Remove},  // Overlay Date
      {0x0008, 0x0025, A::Remove},  // Curve Date
      {0x0008, 0x002A, A::Remove},  // Acquisition DateTime
      {0x0008, 0x0030, A::Empty},   // Study Time
      {0x0008, 0x0031, A::Remove},  // Series Time
      {0x0008, 0x0032, A::Remove},  // Acquisition Time
      {0x0008, 0x0033, A::Empty},   // Content Time
      {0x0008, 0x0034, A::Remove},  // Overlay Time
      {0x0008, 0x0035, A::Remove},  // Curve Time
      {0x0008, 0x0050, A::Empty},   // Accession Number
      {0x0008, 0x0058, A::NewUid},  // Failed SOP Instance UID List
      {0x0008, 0x0080, A::Remove},  // Institution Name
      {0x0008, 0x0081, A::Remove},  // Institution Address
      {0x0008, 0x0082, A::Remove},  // Institution Code Sequence
      {0x0008, 0x0090, A::Empty},   // Referring Physician's Name
      {0x0008, 0x0092, A::Remove},  // Referring Physician's Address
      {0x0008, 0x0094, A::Remove},  // Referring Physician's Telephone Numbers
      {0x0008, 0x0096, A::Remove},  // Referring Physician Identification Sequence
      {0x0008, 0x009C, A::Empty},   // Consulting Physician's Name
      {0x0008, 0x009D, A::Remove},  // Consulting Physician Identification Sequence
      {0x0008, 0x0201, A::Remove},  // Timezone Offset From UTC
      {0x0008, 0x1010, A::Remove},  // Station Name
      {0x0008, 0x1030, A::Remove},  // Study Description
      {0x0008, 0x103E, A::Remove},  // Series Description
      {0x0008, 0x1040, A::Remove},  // Institutional Department Name
      {0x0008, 0x1041, A::Remove},  // Institutional Department Type Code Sequence
      {0x0008, 0x1048, A::Remove},  // Physician(s) of Record
      {0x0008, 0x1049, A::Remove},  // Physician(s) of Record Identification Sequence
      {0x0008, 0x1050, A::Remove},  // Performing Physicians' Name
      {0x0008, 0x1052, A::Remove},  // Performing Physician Identification Sequence
      {0x0008, 0x1060, A::Remove},  // Name of Physician(s) Reading Study
      {0x0008, 0x1062, A::Remove},  // Physician(s) Reading Study Identification Sequence
      {0x0008, 0x1070, A::Remove},  // Operators' Name
      {0x0008, 0x1072, A::Remove},  // Operator Identification Sequence
      {0x0008, 0x1080, A::Remove},  // Admitting Diagnoses Description
      {0x0008, 0x1084, A::Remove},  // Admitting Diagnoses Code Sequence
      {0x0008, 0x1110, A::Remove},  // Referenced Study Sequence
      {0x0008, 0x1111, A::Remove},  // Referenced Performed Procedure Step Sequence
      {0x0008, 0x1120, A::Remove},  // Referenced Patient Sequence
      {0x0008, 0x1155, A::NewUid},  // Referenced SOP Instance UID
      {0x0008, 0x1195, A::NewUid},  // Transaction UID
      {0x0008, 0x2111, A::Remove},  // Derivation Description
      {0x0008, 0x3010, A::NewUid},  // Irradiation Event UID
      {0x0008, 0x4000, A::Remove},  // Identifying Comments
      {0x0010, 0x0010, A::Empty},   // Patient's Name
      {0x0010, 0x0020, A::Empty},   // Patient ID
      {0x0010, 0x0021, A::Remove},  // Issuer of Patient ID
      {0x0010, 0x0030, A::Empty},   // Patient's Birth Date
      {0x0010, 0x0032, A::Remove},  // Patient's Birth Time
      {0x0010, 0x0040, A::Empty},   // Patient's Sex
      {0x0010, 0x0050, A::Remove},  // Patient's Insurance Plan Code Sequence
      {0x0010, 0x0101, A::Remove},  // Patient's Primary Language Code Sequence
      {0x0010, 0x0102, A::Remove},  // Patient's Primary Language Modifier Code Sequence
      {0x0010, 0x1000, A::Remove},  // Other Patient IDs
      {0x0010, 0x1001, A::Remove},  // Other Patient Names
      {0x0010, 0x1002, A::Remove},  // Other Patient IDs Sequence
      {0x0010, 0x1005, A::Remove},  // Patient's Birth Name
      {0x0010, 0x1010, A::Remove},  // Patient's Age
      {0x0010, 0x1020, A::Remove},  // Patient's Size
      {0x0010, 0x1030, A::Remove},  // Patient's Weight
      {0x0010, 0x1040, A::Remove},  // Patient's Address
      {0x0010, 0x1060, A::Remove},  // Patient's Mother's Birth Name
      {0x0010, 0x1080, A::Remove},  // Military Rank
      {0x0010, 0x1081, A::Remove},  // Branch of Service
      {0x0010, 0x1090, A::Remove},  // Medical Record Locator
      {0x0010, 0x2000, A::Remove},  // Medical Alerts
      {0x0010, 0x2110, A::Remove},  // Allergies
      {0x0010, 0x2150, A::Remove},  // Country of Residence
      {0x0010, 0x2152, A::Remove},  // Region of Residence
      {0x0010, 0x2154, A::Remove},  // Patient's Telephone Numbers
      {0x0010, 0x2160, A::Remove},  // Ethnic Group
      {0x0010, 0x2180, A::Remove},  // Occupation
      {0x0010, 0x21A0, A::Remove},  // Smoking Status
      {0x0010, 0x21B0, A::Remove},  // Additional Patient History
      {0x0010, 0x21C0, A::Remove},  // Pregnancy Status
      {0x0010, 0x21D0, A::Remove},  // Last Menstrual Date
      {0x0010, 0x21F0, A::Remove},  // Patient's Religious Preference
      {0x0010, 0x2203, A::Remove},  // Patient's Sex Neutered
      {0x0010, 0x2297, A::Remove},  // Responsible Person
      {0x0010, 0x2299, A::Remove},  // Responsible Organization
      {0x0010, 0x4000, A::Remove},  // Patient Comments
      {0x0018, 0x1000, A::Remove},  // Device Serial Number
      {0x0018, 0x1002, A::NewUid},  // Device UID
      {0x0018, 0x1004, A::Remove},  // Plate ID
      {0x0018, 0x1005, A::Remove},  // Generator ID
      {0x0018, 0x1007, A::Remove},  // Cassette ID
      {0x0018, 0x1008, A::Remove},  // Gantry ID
      {0x0018, 0x1012, A::Remove},  // Date of Secondary Capture
      {0x0018, 0x1014, A::Remove},  // Time of Secondary Capture
      {0x0018, 0x1030, A::Remove},  // Protocol Name
      {0x0018, 0x1200, A::Remove},  // Date of Last Calibration
      {0x0018, 0x1201, A::Remove},  // Time of Last Calibration
      {0x0018, 0x1400, A::Remove},  // Acquisition Device Processing Description
      {0x0018, 0x4000, A::Remove},  // Acquisition Comments
      {0x0018, 0x700A, A::Remove},  // Detector ID
      {0x0018, 0x9074, A::Remove},  // Frame Acquisition DateTime
      {0x0018, 0x9151, A::Remove},  // Frame Reference DateTime
      {0x0018, 0x9424, A::Remove},  // Acquisition Protocol Description
      {0x0018, 0xA003, A::Remove},  // Contribution Description
      {0x0020, 0x000D, A::NewUid},  // Study Instance UID
      {0x0020, 0x000E, A::NewUid},  // Series Instance UID
      {0x0020, 0x0010, A::Empty},   // Study ID
      {0x0020, 0x0052, A::NewUid},  // Frame of Reference UID
      {0x0020, 0x0200, A::NewUid},  // Synchronization Frame of Reference UID
      {0x0020, 0x3401, A::Remove},  // Modifying Device ID
      {0x0020, 0x3404, A::Remove},  // Modifying Device Manufacturer
      {0x0020, 0x3406, A::Remove},  // Modified Image Description
      {0x0020, 0x4000, A::Remove},  // Image Comments
      {0x0020, 0x9161, A::NewUid},  // Concatenation UID
      {0x0020, 0x9164, A::NewUid},  // Dimension Organization UID
      {0x0028, 0x1199, A::NewUid},  // Palette Color Lookup Table UID
      {0x0028, 0x1214, A::NewUid},  // Large Palette Color Lookup Table UID
      {0x0028, 0x4000, A::Remove},  // Image Presentation Comments
      {0x0032, 0x0012, A::Remove},  // Study ID Issuer
      {0x0032, 0x1020, A::Remove},  // Scheduled Study Location
      {0x0032, 0x1021, A::Remove},  // Scheduled Study Location AE Title
      {0x0032, 0x1030, A::Remove},  // Reason for Study
      {0x0032, 0x1032, A::Remove},  // Requesting Physician
      {0x0032, 0x1033, A::Remove},  // Requesting Service
      {0x0032, 0x1060, A::Remove},  // Requested Procedure Description
      {0x0032, 0x1070, A::Remove},  // Requested Contrast Agent
      {0x0032, 0x4000, A::Remove},  // Study Comments
      {0x0038, 0x0004, A::Remove},  // Referenced Patient Alias Sequence
      {0x0038, 0x0010, A::Remove},  // Admission ID
      {0x0038, 0x0011, A::Remove},  // Issuer of Admission ID
      {0x0038, 0x001E, A::Remove},  // Scheduled Patient Institution Residence
      {0x0038, 0x0020, A::Remove},  // Admitting Date
      {0x0038, 0x0021, A::Remove},  // Admitting Time
      {0x0038, 0x0040, A::Remove},  // Discharge Diagnosis Description
      {0x0038, 0x0050, A::Remove},  // Special Needs
      {0x0038, 0x0060, A::Remove},  // Service Episode ID
      {0x0038, 0x0300, A::Remove},  // Current Patient Location
      {0x0038, 0x0400, A::Remove},  // Patient's Institution Residence
      {0x0038, 0x0500, A::Remove},  // Patient State
      {0x0038, 0x4000, A::Remove},  // Visit Comments
      {0x0040, 0x0001, A::Remove},  // Scheduled Station AE Title
      {0x0040, 0x0002, A::Remove},  // Scheduled Procedure Step Start Date
      {0x0040, 0x0003, A::Remove},  // Scheduled Procedure Step Start Time
      {0x0040, 0x0004, A::Remove},  // Scheduled Procedure Step End Date
      {0x0040, 0x0005, A::Remove},  // Scheduled Procedure Step End Time
      {0x0040, 0x0006, A::Remove},  // Scheduled Performing Physician Name
      {0x0040, 0x0007, A::Remove},  // Scheduled Procedure Step Description
      {0x0040, 0x000B, A::Remove},  // Scheduled Performing Physician Identification Sequence
      {0x0040, 0x0010, A::Remove},  // Scheduled Station Name
      {0x0040, 0x0011, A::Remove},  // Scheduled Procedure Step Location
      {0x0040, 0x0012, A::Remove},  // Pre-Medication
      {0x0040, 0x0241, A::Remove},  // Performed Station AE Title
      {0x0040, 0x0242, A::Remove},  // Performed Station Name
      {0x0040, 0x0243, A::Remove},  // Performed Location
      {0x0040, 0x0244, A::Remove},  // Performed Procedure Step Start Date
      {0x0040, 0x0245, A::Remove},  // Performed Procedure Step Start Time
      {0x0040, 0x0250, A::Remove},  // Performed Procedure Step End Date
      {0x0040, 0x0251, A::Remove},  // Performed Procedure Step End Time
      {0x0040, 0x0253, A::Remove},  // Performed Procedure Step ID
      {0x0040, 0x0254, A::Remove},  // Performed Procedure Step Description
      {0x0040, 0x0275, A::Remove},  // Request Attributes Sequence
      {0x0040, 0x0280, A::Remove},  // Comments on the Performed Procedure Step
      {0x0040, 0x0555, A::Remove},  // Acquisition Context Sequence
      {0x0040, 0x1001, A::Remove},  // Requested Procedure ID
      {0x0040, 0x1004, A::Remove},  // Patient Transport Arrangements
      {0x0040, 0x1005, A::Remove},  // Requested Procedure Location
      {0x0040, 0x1010, A::Remove},  // Names of Intended Recipients of Results
      {0x0040, 0x1011, A::Remove},  // Intended Recipients of Results Identification Sequence
      {0x0040, 0x1101, A::Remove},  // Person Identification Code Sequence
      {0x0040, 0x1102, A::Remove},  // Person's Address
      {0x0040, 0x1103, A::Remove},  // Person's Telephone Numbers
      {0x0040, 0x1400, A::Remove},  // Requested Procedure Comments
      {0x0040, 0x2001, A::Remove},  // Reason for the Imaging Service Request
      {0x0040, 0x2008, A::Remove},  // Order Entered By
      {0x0040, 0x2009, A::Remove},  // Order Enterer's Location
      {0x0040, 0x2010, A::Remove},  // Order Callback Phone Number
      {0x0040, 0x2016, A::Remove},  // Placer Order Number / Imaging Service Request
      {0x0040, 0x2017, A::Remove},  // Filler Order Number / Imaging Service Request
      {0x0040, 0x2400, A::Remove},  // Imaging Service Request Comments
      {0x0040, 0x3001, A::Remove},  // Confidentiality Constraint on Patient Data Description
      {0x0040, 0xA027, A::Remove},  // Verifying Organization
      {0x0040, 0xA073, A::Remove},  // Verifying Observer Sequence
      {0x0040, 0xA075, A::Remove},  // Verifying Observer Name
      {0x0040, 0xA078, A::Remove},  // Author Observer Sequence
      {0x0040, 0xA07A, A::Remove},  // Participant Sequence
      {0x0040, 0xA07C, A::Remove},  // Custodial Organization Sequence
      {0x0040, 0xA030, A::Remove},  // Verification DateTime
      {0x0040, 0xA032, A::Remove},  // Observation DateTime
      {0x0040, 0xA120, A::Remove},  // DateTime
      {0x0040, 0xA121, A::Remove},  // Date
      {0x0040, 0xA122, A::Remove},  // Time
      {0x0040, 0xA124, A::NewUid},  // UID
      {0x0040, 0xA171, A::NewUid},  // Observation UID
      {0x0040, 0xA730, A::Remove},  // Content Sequence (an image's SR content: free text)
      {0x0040, 0xDB0C, A::NewUid},  // Template Extension Organization UID
      {0x0040, 0xDB0D, A::NewUid},  // Template Extension Creator UID
      {0x0070, 0x0084, A::Empty},   // Content Creator's Name
      {0x0070, 0x0086, A::Remove},  // Content Creator's Identification Code Sequence
      {0x0070, 0x031A, A::NewUid},  // Fiducial UID
      {0x0088, 0x0140, A::NewUid},  // Storage Media File-set UID
      {0x0400, 0x0100, A::Remove},  // Digital Signature UID
      {0x0400, 0x0402, A::Remove},  // Referenced Digital Signature Sequence
      {0x0400, 0x0403, A::Remove},  // Referenced SOP Instance MAC Sequence
      {0x0400, 0x0404, A::Remove},  // MAC
      {0x0400, 0x0550, A::Remove},  // Modified Attributes Sequence
      {0x0400, 0x0561, A::Remove},  // Original Attributes Sequence
      {0x3006, 0x0024, A::NewUid},  // Referenced Frame of Reference UID
      {0x3006, 0x00C2, A::NewUid},  // Related Frame of Reference UID
      {0x4000, 0x0010, A::Remove},  // Arbitrary
      {0x4000, 0x4000, A::Remove},  // Text Comments
      {0x4008, 0x0042, A::Remove},  // Results ID Issuer
      {0x4008, 0x0114, A::Remove},  // Physician Approving Interpretation
      {0x4008, 0x0119, A::Remove},  // Distribution Name
      {0x4008, 0x011A, A::Remove},  // Distribution Address
      {0x4008, 0x0202, A::Remove},  // Interpretation ID Issuer
      {0x4008, 0x4000, A::Remove},  // Results Comments
      {0xFFFA, 0xFFFA, A::Remove},  // Digital Signatures Sequence
      {0xFFFC, 0xFFFC, A::Remove},  // Data Set Trailing Padding
  };
  return table;
}

}  // namespace voxray::report
