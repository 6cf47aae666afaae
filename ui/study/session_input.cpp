// The session's "input" (the study's data, and the fusion overlay's): its path written
// relative to the session where the two move together, and read back beside the session
// first, then where it was saved; movedDataMessage() names the places tried.
#include "session_sections.h"

#include <filesystem>
#include <iterator>

#include "voxray/engine/input_flags.h"

namespace voxray {

namespace session_detail {

namespace {

namespace fs = std::filesystem;

fs::path folderOf(const std::string& sessionPath) {
  return fs::absolute(fs::path(sessionPath)).lexically_normal().parent_path();
}

// PATH absolute and normal, without a trailing separator.
fs::path normalAbsolute(const std::string& path) {
  fs::path p = fs::absolute(fs::path(path)).lexically_normal();
  return p.has_filename() ? p : p.parent_path();
}

}  // namespace

Json inputJson(const SessionInput& in, const std::string& sessionPath) {
  Json j;
  if (in.path.empty()) {
    j["path"] = "";
  } else {
    const fs::path absolute = normalAbsolute(in.path), folder = folderOf(sessionPath);
    // Relative when the two share a folder below the root ("/data/study" beside
    // "/data/sessions"): such trees move together; "../../../work/..." would not.
    auto top = [](const fs::path& p) {
      return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin());
    };
    const fs::path relative = top(absolute) == top(folder) && !top(folder).empty()
                                  ? absolute.lexically_relative(folder)
                                  : fs::path();
    j["path"] = (relative.empty() ? absolute : relative).string();
    j["absolute-path"] = absolute.string();
  }
  j["flags"] = Json::object();
  for (const auto& [key, value] : in.flags) j["flags"][key] = value;
  return j;
}

// An input object (the study's "input", the overlay's "fusion.input"), FIELD naming it: its
// path resolved beside the session first (a folder moved with its session), then where it was
// saved; MISSING lists the paths tried when it is at none.
void readInputObject(Reader& r, const Json& in, const std::string& field,
                     const std::string& sessionPath, SessionInput& out,
                     std::vector<std::string>& missing) {
  r.warnUnknown(in, field + ".", {"path", "absolute-path", "flags"});
  const std::string written = r.text(r.require(in, field + ".path", "path"), field + ".path");
  if (in.contains("flags")) {
    const Json& flags = r.object(in, field + ".flags", "flags");
    for (const auto& item : flags.items()) {
      const std::string flag = field + ".flags." + item.key();
      try {
        findInputFlagSpec(item.key());
      } catch (const Error&) {
        r.unknown(flag);
        continue;
      }
      out.flags[item.key()] = r.valueText(item.value(), flag);
    }
    try {
      loadOptionsFromFlags(out.flags);
    } catch (const Error& e) {
      r.fail(field + ".flags", std::string("is wrong: ") + e.what());
    }
  }
  if (written.empty()) return;  // the embedded head phantom
  std::vector<fs::path> candidates;
  const fs::path p(written);
  candidates.push_back(p.is_absolute() ? p : (folderOf(sessionPath) / p).lexically_normal());
  if (in.contains("absolute-path")) {
    fs::path a(r.text(in.at("absolute-path"), field + ".absolute-path"));
    if (a != candidates.front()) candidates.push_back(a);
  }
  std::error_code ec;
  for (const fs::path& c : candidates)
    if (fs::exists(c, ec)) {
      out.path = c.string();
      return;
    }
  out.path = candidates.front().string();
  for (const fs::path& c : candidates) missing.push_back(c.string());
}

void readInput(Reader& r, const Json& root, const std::string& sessionPath, SessionRead& out) {
  readInputObject(r, r.object(root, "input", "input"), "input", sessionPath, out.session.input,
                  out.missingInput);
}

}  // namespace session_detail

std::string movedDataMessage(const std::string& sessionPath, const std::vector<std::string>& tried,
                             const std::string& fix) {
  std::string where;
  for (size_t i = 0; i < tried.size(); ++i)
    where += (i ? (i + 1 == tried.size() ? " nor at " : ", ") : "") + tried[i];
  return "session " + sessionPath + ": its data is missing (not at " + where +
         "); the data moved or was deleted. " + fix;
}

}  // namespace voxray
