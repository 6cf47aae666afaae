// The Basic Profile applied with dcmdata: each dataset is edited in memory (item by item,
// down every sequence) and saved with a new meta header, pixel data untouched in its own
// transfer syntax, so the copy decodes to the same voxels.
#include "voxray/io/anonymise.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>

#include "basic_profile.h"
#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"

namespace voxray {
namespace fs = std::filesystem;
using report::Action;

namespace {

struct Export {
  const AnonymiseOptions& options;
  std::map<std::string, std::string> uids;  // old UID -> new, for this export

  std::string newUid(const std::string& old) {
    auto it = uids.find(old);
    if (it != uids.end()) return it->second;
    char uid[100];
    dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT);
    return uids[old] = uid;
  }
};

std::optional<Action> profileAction(const DcmTagKey& t) {
  static const std::map<std::pair<uint16_t, uint16_t>, Action> table = [] {
    std::map<std::pair<uint16_t, uint16_t>, Action> m;
    for (const auto& a : report::basicProfile()) m[{a.group, a.element}] = a.action;
    return m;
  }();
  auto it = table.find({t.getGroup(), t.getElement()});
  if (it == table.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> values(DcmElement& e) {
  OFString all;
  e.getOFStringArray(all);
  std::vector<std::string> out;
  std::stringstream in(all.c_str());
  std::string v;
  while (std::getline(in, v, '\\')) out.push_back(v);
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (size_t n = 0; n < v.size(); ++n) s += (n ? "\\" : "") + v[n];
  return s;
}

// YYYYMMDD plus DAYS (the Modified Dates option); empty when it is no date.
std::string shiftDate(const std::string& d, int days) {
  if (d.size() < 8 || !std::all_of(d.begin(), d.begin() + 8, ::isdigit)) return "";
  std::tm t{};
  t.tm_year = std::stoi(d.substr(0, 4)) - 1900;
  t.tm_mon = std::stoi(d.substr(4, 2)) - 1;
  t.tm_mday = std::stoi(d.substr(6, 2)) + days;
  t.tm_hour = 12;  // noon: no daylight saving edge moves the day
  const std::time_t s = timegm(&t);
  std::tm out{};
  gmtime_r(&s, &out);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y%m%d", &out);
  return buf + d.substr(8);  // a DT keeps its time and offset
}

bool isCurveOrOverlayText(const DcmTagKey& t) {
  const uint16_t g = t.getGroup();
  if ((g & 0xFF00) == 0x5000) return true;  // retired curves
  return (g & 0xFF01) == 0x6000 && (t.getElement() == 0x3000 || t.getElement() == 0x4000);
}

void clean(DcmItem& item, Export& x) {
  std::vector<DcmTagKey> drop;
  for (unsigned long n = 0; n < item.card(); ++n) {
    DcmElement* e = item.getElement(n);
    const DcmTagKey tag = e->getTag();
    const DcmEVR vr = e->ident();
    if (tag.isPrivate() || isCurveOrOverlayText(tag)) {
      drop.push_back(tag);
      continue;
    }
    const bool temporal = vr == EVR_DA || vr == EVR_DT || vr == EVR_TM;
    std::optional<Action> action = profileAction(tag);
    // Keep and Shift are PS3.15's Retain Longitudinal Temporal Information options (full or
    // modified dates): the profile's dates and times stay (shifted) instead of going.
    if (action && temporal && x.options.dates != DateHandling::Remove) action.reset();
    if (action) {
      switch (*action) {
        case Action::Remove:
          drop.push_back(tag);
          continue;
        case Action::Empty:
          if (vr == EVR_SQ)
            static_cast<DcmSequenceOfItems*>(e)->clear();
          else
            e->putString("");
          continue;
        case Action::Dummy:
          e->putString(vr == EVR_DA ? "19000101" : "ANONYMOUS");
          continue;
        case Action::NewUid: {
          auto v = values(*e);
          for (auto& u : v)
            if (!u.empty()) u = x.newUid(u);
          e->putOFStringArray(joined(v).c_str());
          continue;
        }
      }
    }
    if (x.options.dates == DateHandling::Shift && (vr == EVR_DA || vr == EVR_DT)) {
      auto v = values(*e);
      for (auto& d : v) d = shiftDate(d, x.options.shiftDays);
      e->putOFStringArray(joined(v).c_str());
    }
    if (vr == EVR_SQ) {
      auto* sq = static_cast<DcmSequenceOfItems*>(e);
      for (unsigned long i = 0; i < sq->card(); ++i) clean(*sq->getItem(i), x);
    }
  }
  for (const auto& t : drop) item.findAndDeleteElement(t, OFFalse, OFFalse);
}

void addCode(DcmItem& item, const char* value, const char* meaning) {
  DcmItem* code = nullptr;
  if (item.findOrCreateSequenceItem(DCM_DeidentificationMethodCodeSequence, code, -2).bad()) return;
  code->putAndInsertString(DCM_CodeValue, value);
  code->putAndInsertString(DCM_CodingSchemeDesignator, "DCM");
  code->putAndInsertString(DCM_CodeMeaning, meaning);
}

void markDeidentified(DcmDataset& d, const AnonymiseOptions& o) {
  d.putAndInsertString(DCM_PatientName, o.patientName.c_str());
  d.putAndInsertString(DCM_PatientID, o.patientId.c_str());
  d.putAndInsertString(DCM_PatientIdentityRemoved, "YES");
  d.putAndInsertString(DCM_DeidentificationMethod, "PS3.15 E.1-1 Basic Profile (Voxray)");
  addCode(d, "113100", "Basic Application Confidentiality Profile");
  if (o.dates == DateHandling::Keep)
    addCode(d, "113106", "Retain Longitudinal Temporal Information Full Dates Option");
  if (o.dates == DateHandling::Shift)
    addCode(d, "113107", "Retain Longitudinal Temporal Information Modified Dates Option");
  d.putAndInsertString(DCM_LongitudinalTemporalInformationModified,
                       o.dates == DateHandling::Keep    ? "UNMODIFIED"
                       : o.dates == DateHandling::Shift ? "MODIFIED"
                                                        : "REMOVED");
}

bool inside(const fs::path& child, const fs::path& parent) {
  auto c = child.begin(), p = parent.begin();
  for (; p != parent.end(); ++p, ++c)
    if (c == child.end() || *c != *p) return false;
  return true;
}

std::string str(DcmItem& d, const DcmTagKey& tag) {
  OFString v;
  d.findAndGetOFString(tag, v);
  return v.c_str();
}

}  // namespace

AnonymiseResult anonymise(const std::string& input, const std::string& output,
                          const AnonymiseOptions& options) {
  std::error_code ec;
  if (input.empty() || !fs::exists(input, ec))
    throw inputError("anonymise: " + input + " does not exist: give a DICOM folder or file");
  if (output.empty()) throw inputError("anonymise: give the output folder (-o DIR)");
  const fs::path in = fs::weakly_canonical(input, ec), out = fs::weakly_canonical(output, ec);
  const fs::path inFolder = fs::is_directory(in) ? in : in.parent_path();
  if (inside(out, inFolder))
    throw inputError("anonymise: the output folder " + output +
                     " lies inside the input's folder; never written into: choose a folder "
                     "outside it");
  if (inside(inFolder, out))
    throw inputError("anonymise: the output folder " + output +
                     " contains the input: choose a separate, empty folder");
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw inputError("anonymise: " + output + " is a file: give a folder");
  if (fs::exists(out, ec) && !fs::is_empty(out, ec) && !options.force)
    throw inputError("anonymise: " + output +
                     " exists and is not empty; give --force to write into it");

  std::vector<fs::path> files;
  if (fs::is_directory(in)) {
    for (auto it = fs::recursive_directory_iterator(
             in, fs::directory_options::skip_permission_denied, ec);
         it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (ec) break;
      if (it->is_regular_file(ec)) files.push_back(it->path());
    }
  } else {
    files.push_back(in);
  }
  std::sort(files.begin(), files.end());

  AnonymiseResult result;
  Export x{options, {}};
  std::map<std::string, std::pair<int, int>> series;  // new series UID -> folder number, count
  for (const auto& path : files) {
    DcmFileFormat file;
    if (file.loadFile(path.c_str()).bad()) {
      ++result.skipped;
      continue;
    }
    DcmDataset& d = *file.getDataset();
    const std::string seriesUid = str(d, DCM_SeriesInstanceUID);
    if (str(d, DCM_SOPInstanceUID).empty() || str(d, DCM_SOPClassUID).empty() ||
        str(d, DCM_SOPClassUID) == UID_MediaStorageDirectoryStorage ||
        (!options.seriesUid.empty() && seriesUid != options.seriesUid)) {
      ++result.skipped;
      continue;
    }
    if (str(d, DCM_BurnedInAnnotation) == "YES") {
      ++result.burnedIn;
      continue;
    }
    if (!result.written) fs::create_directories(out, ec);
    clean(d, x);
    markDeidentified(d, options);
    const std::string newSeries = str(d, DCM_SeriesInstanceUID);
    auto& s = series.try_emplace(newSeries, int(series.size()) + 1, 0).first->second;
    char name[64];
    std::snprintf(name, sizeof name, "S%03d/IM%05d.dcm", s.first, ++s.second);
    const fs::path target = out / name;
    fs::create_directories(target.parent_path(), ec);
    // A new meta header: the old one names the source's SOP Instance UID and sender.
    dicomwrite::saveAtomically(file, target.string(), "anonymised copy",
                               dicomwrite::Encoding::asReadNewMeta);
    result.files.push_back(name);
    ++result.written;
  }
  if (!result.written)
    throw inputError(
        "anonymise: no DICOM image under " + input +
        (options.seriesUid.empty() ? std::string() : " in series " + options.seriesUid) + " (" +
        std::to_string(result.skipped) + " other files)");
  return result;
}

}  // namespace voxray
