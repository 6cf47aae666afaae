#include "raw_slice_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
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

// The number a file name ends in ("CThead.57" -> 57); none for names without one, or with
// more digits than any real stack needs.
std::optional<long long> trailingNumber(const std::string& name) {
  size_t start = name.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
  const size_t digits = name.size() - start;
  if (digits == 0 || digits > 15) return std::nullopt;
  return std::stoll(name.substr(start));
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
  std::vector<SliceFile> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code typeError;
    if (!it->is_regular_file(typeError)) continue;
    const std::string name = it->path().filename().string();
    if (auto n = trailingNumber(name)) files.push_back({*n, it->path().string()});
  }
  if (ec) throw inputError(folder + ": cannot list the folder (" + ec.message() + ")");
  if (files.empty()) {
    throw inputError(folder +
                     ": no slice files in this folder (raw slices are files whose names end in "
                     "their number, like CThead.1)");
  }
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

std::vector<SliceFile> listSlicePattern(const std::string& pattern, const SliceRange& range) {
  const Pattern p = parsePattern(pattern);
  if (!range) {
    throw inputError(pattern +
                     ": a slice pattern needs the slice numbers: give --raw-range FIRST-LAST "
                     "(e.g. 1-113)");
  }
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
