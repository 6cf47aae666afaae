#include "raw_slice_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <system_error>

#include "file_kind.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::detail {
namespace {

std::string fileName(const SliceFile& f) { return fs::path(f.path).filename().string(); }

std::string numbers(long long a, long long b) {
  return a == b ? std::to_string(a) : std::to_string(a) + "-" + std::to_string(b);
}

// Slices first..last are absent; `before`/`after` are the files around the gap, if any.
Error missingSlices(long long first, long long last, const SliceFile* before,
                    const SliceFile* after, const std::string& where) {
  std::string m = (first == last ? "slice " : "slices ") + numbers(first, last) + " missing";
  if (before && after) {
    m += " between " + fileName(*before) + " and " + fileName(*after);
  } else if (after) {
    m += " before " + fileName(*after);
  } else if (before) {
    m += " after " + fileName(*before);
  }
  return inputError(m + " in " + where +
                    ": a stack must be complete; load part of it with --raw-range FIRST-LAST");
}

// `files` are sorted by number, unique and within [first, last]; every number must be there.
void requireComplete(const std::vector<SliceFile>& files, long long first, long long last,
                     const std::string& where) {
  long long expected = first;
  const SliceFile* previous = nullptr;
  for (const auto& f : files) {
    if (f.number != expected) throw missingSlices(expected, f.number - 1, previous, &f, where);
    previous = &f;
    ++expected;
  }
  if (expected <= last) throw missingSlices(expected, last, previous, nullptr, where);
}

// A file name's slice number and what follows it: "CThead.57" -> 57 and "", "001.tif" ->
// 1 and ".tif" (a number before a short extension). None for names without one, or with
// more digits than any real stack needs.
struct NumberedName {
  long long number = 0;
  std::string suffix;
};

std::optional<long long> trailingNumber(const std::string& name) {
  size_t start = name.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
  const size_t digits = name.size() - start;
  if (digits == 0 || digits > 15) return std::nullopt;
  return std::stoll(name.substr(start));
}

std::optional<NumberedName> numberedName(const std::string& name) {
  if (auto n = trailingNumber(name)) return NumberedName{*n, ""};
  const size_t dot = name.rfind('.');
  constexpr size_t kMaxExtension = 8;  // ".tif", ".raw", ".dcm", ".img", ".tiff"
  if (dot == std::string::npos || dot == 0 || name.size() - dot > kMaxExtension ||
      name.size() - dot < 2)
    return std::nullopt;
  if (auto n = trailingNumber(name.substr(0, dot))) return NumberedName{*n, name.substr(dot)};
  return std::nullopt;
}

struct Pattern {
  std::string before, after;
  int width = 0;  // %0Nd: zero-padded to N digits
  std::string format(long long n) const {
    std::string digits = std::to_string(n);
    if (int(digits.size()) < width) digits.insert(0, size_t(width) - digits.size(), '0');
    return before + digits + after;
  }
};

// Parsed by hand rather than handed to snprintf: a user's string must never be a format.
Pattern parsePattern(const std::string& text) {
  auto bad = [&] {
    return inputError(text + ": a slice pattern needs exactly one %d or %0Nd (like CThead.%d or " +
                      "slice%03d.raw); write %% for a literal %");
  };
  Pattern p;
  std::string* out = &p.before;
  bool found = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      *out += text[i];
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '%') {
      *out += '%';
      ++i;
      continue;
    }
    size_t j = i + 1;
    int width = 0;
    if (j < text.size() && text[j] == '0') {
      for (++j; j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])); ++j) {
        width = width * 10 + (text[j] - '0');
        if (width > 18) throw bad();
      }
    }
    if (found || j >= text.size() || text[j] != 'd') throw bad();
    found = true;
    p.width = width;
    out = &p.after;
    i = j;
  }
  if (!found) throw bad();
  return p;
}

// The first and last numbers of the files PATTERN names, found by listing its folder: the
// range need not be given. Throws Error (Input) when no file matches.
std::pair<int, int> patternRange(const Pattern& p, const std::string& pattern) {
  const auto needRange = [&](const std::string& why) {
    return inputError(pattern + ": " + why + "; give the slice numbers with --raw-range " +
                      "FIRST-LAST (e.g. 1-113)");
  };
  if (p.after.find('/') != std::string::npos)
    throw needRange("the number is in a folder's name, so the files cannot be listed");
  const fs::path before(p.before);
  const std::string prefix = before.filename().string();
  fs::path folder = before.parent_path();
  if (folder.empty()) folder = ".";
  long long lo = -1, hi = -1;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + p.after.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - p.after.size(), p.after.size(), p.after) != 0)
      continue;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - p.after.size());
    if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(),
                                          [](unsigned char c) { return std::isdigit(c) != 0; }))
      continue;
    const long long n = std::stoll(digits);
    if (fs::path(p.format(n)).filename().string() != name) continue;  // "1.tif" for %03d
    lo = lo < 0 ? n : std::min(lo, n);
    hi = std::max(hi, n);
  }
  if (ec) throw needRange("cannot list " + folder.string() + " (" + ec.message() + ")");
  if (lo < 0) throw needRange("no file in " + folder.string() + " matches it");
  return {int(lo), int(hi)};
}

}  // namespace

long long sliceCount(const std::pair<int, int>& range) {
  const auto [first, last] = range;
  if (first < 0 || first > last) {
    throw inputError("slice range " + std::to_string(first) + "-" + std::to_string(last) +
                     ": give FIRST-LAST with 0 <= FIRST <= LAST");
  }
  return (long long)last - first + 1;
}

std::vector<SliceFile> listSliceFolder(const std::string& folder, const SliceRange& range) {
  if (range) sliceCount(*range);
  // By what follows the number: the largest group is the stack (CThead.1 ... beside a
  // notes2.txt, or 001.tif ... beside a readme).
  std::map<std::string, std::vector<SliceFile>> bySuffix;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code typeError;
    if (!it->is_regular_file(typeError)) continue;
    const std::string name = it->path().filename().string();
    if (auto n = numberedName(name))
      bySuffix[n->suffix].push_back({n->number, it->path().string()});
  }
  if (ec) throw inputError(folder + ": cannot list the folder (" + ec.message() + ")");
  if (bySuffix.empty()) {
    throw inputError(folder +
                     ": no slice files in this folder (raw slices are files whose names end in "
                     "their number, like CThead.1 or 001.raw)");
  }
  auto largest = bySuffix.begin();
  for (auto it = bySuffix.begin(); it != bySuffix.end(); ++it)
    if (it->second.size() > largest->second.size()) largest = it;
  for (const auto& [suffix, group] : bySuffix) {
    if (&group != &largest->second && group.size() == largest->second.size()) {
      const auto shown = [](const std::string& x) { return x.empty() ? "no extension" : x; };
      throw inputError(folder + ": " + std::to_string(group.size()) + " numbered files each with " +
                       shown(largest->first) + " and " + shown(suffix) +
                       ": which are the slices? Give a pattern such as " + folder + "/%03d" +
                       largest->first + ", or move the others out");
    }
  }
  std::vector<SliceFile> files = std::move(largest->second);
  std::sort(files.begin(), files.end(),
            [](const SliceFile& a, const SliceFile& b) { return a.number < b.number; });
  for (size_t i = 1; i < files.size(); ++i) {
    if (files[i].number == files[i - 1].number) {
      throw inputError(folder + ": " + fileName(files[i - 1]) + " and " + fileName(files[i]) +
                       " both have slice number " + std::to_string(files[i].number) +
                       "; move one of them out of the folder");
    }
  }

  long long first = files.front().number, last = files.back().number;
  if (range) {
    // Plain copies: clang 14 cannot capture structured bindings in a lambda.
    const int lo = range->first, hi = range->second;
    const auto outside = [&](const SliceFile& f) { return f.number < lo || f.number > hi; };
    std::vector<SliceFile> inRange;
    std::copy_if(files.begin(), files.end(), std::back_inserter(inRange),
                 [&](const SliceFile& f) { return !outside(f); });
    if (inRange.empty()) {
      throw inputError(folder + ": no slice files numbered " + numbers(lo, hi) +
                       " (the folder has " + numbers(first, last) + ")");
    }
    files = std::move(inRange);
    first = lo;
    last = hi;
  }
  requireComplete(files, first, last, folder);
  return files;
}

std::vector<SliceFile> listSlicePattern(const std::string& pattern, const SliceRange& given) {
  const Pattern p = parsePattern(pattern);
  const SliceRange range = given ? given : patternRange(p, pattern);
  sliceCount(*range);
  const auto [first, last] = *range;
  // Stops at the first gap: a range of two billion names must not be walked when slice 4
  // is already absent. The message says how far the gap goes, looking a bounded way ahead.
  constexpr long long kLookAhead = 1000;
  const auto exists = [](const std::string& path) {
    std::error_code ec;
    return fs::exists(path, ec);
  };
  std::vector<SliceFile> files;
  for (long long n = first; n <= last; ++n) {
    SliceFile f{n, p.format(n)};
    if (exists(f.path)) {
      refuseSpecialFile(f.path);
      files.push_back(std::move(f));
      continue;
    }
    const long long horizon = std::min<long long>(last, n + kLookAhead);
    long long next = n + 1;
    while (next <= horizon && !exists(p.format(next))) ++next;
    const SliceFile* before = files.empty() ? nullptr : &files.back();
    if (next <= horizon) {
      const SliceFile after{next, p.format(next)};
      throw missingSlices(n, next - 1, before, &after, pattern);
    }
    if (!before) {
      throw inputError(pattern + ": no files for slices " + numbers(n, horizon) +
                       " (the first would be " + f.path + ")");
    }
    throw missingSlices(n, horizon, before, nullptr, pattern);
  }
  return files;  // complete: every number in the range was found, or the loop threw
}

}  // namespace voxray::detail
