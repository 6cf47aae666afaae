#include "nifti_hints.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <set>

namespace voxray::formats {
namespace {

// TEXT's words: runs of letters and digits ("PET/CT" gives PET and CT), as written.
std::set<std::string> wordsOf(const std::string& text) {
  std::set<std::string> words;
  std::string word;
  for (char c : text + " ") {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      word += c;
    } else if (!word.empty()) {
      words.insert(word);
      word.clear();
    }
  }
  return words;
}

// Acronyms count as written ("HU", not the name "Hu"; "PET", not "pet"); a long word in any
// case ("Hounsfield").
bool any(const std::set<std::string>& words, std::initializer_list<const char*> wanted) {
  for (const std::string& w : words)
    for (const char* x : wanted) {
      const std::string want = x;
      if (w == want) return true;
      if (want.size() >= 6 && w.size() == want.size() &&
          std::equal(w.begin(), w.end(), want.begin(), [](char a, char b) {
            return std::tolower(static_cast<unsigned char>(a)) ==
                   std::tolower(static_cast<unsigned char>(b));
          }))
        return true;
    }
  return false;
}

}  // namespace

ValueHint niftiValueHint(const std::string& descrip, const std::string& intentName) {
  const std::set<std::string> words = wordsOf(descrip + " " + intentName);
  const bool pet = any(words, {"PET", "SUV", "SUVbw", "SUVlbm", "FDG"});
  const bool mr = any(words, {"MR", "MRI", "T1w", "T2w", "FLAIR", "BOLD", "DWI"});
  const bool ct = any(words, {"CT", "CTA", "HU", "Hounsfield"});
  ValueHint h;
  if (pet && !mr) {
    h.modality = "PT";
    if (any(words, {"SUV", "SUVbw", "SUVlbm"})) h.unit = "SUV";
  } else if (mr && !ct) {
    h.modality = "MR";
  } else if (ct && !mr) {
    h.modality = "CT";
    h.unit = "HU";
  }
  return h;
}

}  // namespace voxray::formats
