#pragma once
// Reading a session file's JSON (session*.cpp only): the Reader names the file and the field in
// every error and collects the warnings about fields it ignores or misses.
#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"

namespace voxray::session_detail {

// Ordered: a session reads top to bottom as written, and measurements keep their key order.
using Json = nlohmann::ordered_json;

// Unknown fields are listed up to kListedUnknown lines.
constexpr size_t kListedUnknown = 20;

// TEXT as a message may show it: bytes that are not UTF-8 become U+FFFD and control
// characters \u escapes (the JSON library's own string escaping), so a hostile file puts no
// raw bytes or terminal escapes into an error.
inline std::string shown(const std::string& text) {
  const std::string quoted = Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
  return quoted.substr(1, quoted.size() - 2);
}

// Reads one session's JSON, naming the file and the field in every error, and collecting
// the warnings about fields it ignores or misses.
class Reader {
 public:
  explicit Reader(std::string sessionPath) : path_(std::move(sessionPath)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw inputError("session " + path_ + ": field '" + shown(field) + "' " + shown(what));
  }

  // OBJ's KEY (FIELD names it); a missing one is an error.
  const Json& require(const Json& obj, const std::string& field, const std::string& key) const {
    auto it = obj.find(key);
    if (it == obj.end())
      throw inputError("session " + path_ + ": the required field '" + field +
                       "' is missing; the file is damaged or not a Voxray session (save the "
                       "session again)");
    return *it;
  }
  const Json& object(const Json& obj, const std::string& field, const std::string& key) const {
    const Json& v = require(obj, field, key);
    if (!v.is_object()) fail(field, "must be an object { ... }");
    return v;
  }
  std::string text(const Json& v, const std::string& field) const {
    if (!v.is_string()) fail(field, "must be a string");
    return v.get<std::string>();
  }
  double number(const Json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "must be a number");
    return v.get<double>();
  }
  std::vector<int> wholes(const Json& v, const std::string& field, size_t count) const {
    const std::string want = "must be an array of " + std::to_string(count) + " whole numbers";
    if (!v.is_array() || v.size() != count) fail(field, want);
    std::vector<int> out;
    for (const Json& n : v) {
      if (!n.is_number_integer()) fail(field, want);
      out.push_back(n.get<int>());
    }
    return out;
  }
  std::vector<double> numbers(const Json& v, const std::string& field, size_t count) const {
    const std::string want = "must be an array of " + std::to_string(count) + " numbers";
    if (!v.is_array() || v.size() != count) fail(field, want);
    std::vector<double> out;
    for (const Json& n : v) out.push_back(number(n, field));
    return out;
  }
  // A declared value as its text: strings as they are, numbers and booleans as a hand
  // editor would expect them to read.
  std::string valueText(const Json& v, const std::string& field) const {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
    if (v.is_number()) return v.dump();
    fail(field, "must be a string, a number or true/false");
  }
  // Keys of OBJ (under PARENT) not in KNOWN: warned about, ignored.
  void warnUnknown(const Json& obj, const std::string& parent,
                   const std::vector<std::string>& known) {
    for (const auto& item : obj.items())
      if (std::find(known.begin(), known.end(), item.key()) == known.end())
        unknown(parent + item.key());
  }
  void unknown(const std::string& field) {
    if (++unknown_ <= kListedUnknown)
      warnings.push_back("unknown field '" + shown(field) + "' ignored");
  }
  // The warnings, with a line for the unknown fields beyond those listed.
  std::vector<std::string> allWarnings() {
    if (unknown_ > kListedUnknown)
      warnings.push_back("and " + std::to_string(unknown_ - kListedUnknown) +
                         " more unknown fields ignored");
    return std::move(warnings);
  }

  std::vector<std::string> warnings;

 private:
  size_t unknown_ = 0;
  std::string path_;
};

}  // namespace voxray::session_detail
