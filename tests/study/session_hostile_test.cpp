// Hostile session files (issue 39): hundreds of thousands of keys made reading take minutes
// (the JSON library's ordered objects compare each key with every earlier one), and errors
// echoed the file's raw bytes, invalid UTF-8 and terminal escapes included.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

#include "session.h"
#include "voxray/io/error.h"

using namespace voxray;
using Json = nlohmann::ordered_json;

namespace {

std::string readTextError(const std::string& text) {
  try {
    sessionFromJson(text, "s.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    return e.what();
  }
  ADD_FAILURE() << "read without an error";
  return "";
}

// A saved default session with N unknown fields "kI" added to its render object.
std::string withUnknownRenderFields(size_t n) {
  std::string text = sessionToJson(Session{}, "s.json");
  std::string keys;
  for (size_t i = 0; i < n; ++i) keys += "\"k" + std::to_string(i) + "\": 0, ";
  text.insert(text.find("\"render\": {") + 11, keys);
  return text;
}

bool validUtf8(const std::string& s) {
  try {
    (void)Json(s).dump();  // throws type_error 316 on invalid UTF-8
    return true;
  } catch (const Json::exception&) {
    return false;
  }
}

TEST(SessionHostile, AnObjectOfAbsurdlyManyFieldsIsRefusedQuickly) {
  const std::string text = withUnknownRenderFields(300000);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(readTextError(text),
            "session s.json: an object holds more than 1000 fields; not a Voxray session (or a "
            "damaged one)");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// Objects of up to 1000 fields each, but many: 2,000 such objects took 10 s.
TEST(SessionHostile, AbsurdlyManyFieldsInAllAreRefused) {
  std::string text = sessionToJson(Session{}, "s.json");
  std::string many;
  for (int o = 0; o < 150; ++o) {
    many += o ? ", {" : "{";
    for (int k = 0; k < 1000; ++k) many += (k ? ", \"k" : "\"k") + std::to_string(k) + "\": 0";
    many += "}";
  }
  text.replace(text.find("\"measurements\": []"), 18, "\"measurements\": [" + many + "]");
  EXPECT_EQ(readTextError(text),
            "session s.json: it holds more than 100000 fields in all; not a Voxray session (or a "
            "damaged one)");
}

TEST(SessionHostile, ManyUnknownFieldsAreListedBriefly) {
  const SessionRead read = sessionFromJson(withUnknownRenderFields(900), "s.json");
  ASSERT_EQ(read.warnings.size(), 21u);
  EXPECT_EQ(read.warnings[0], "unknown field 'render.k0' ignored");
  EXPECT_EQ(read.warnings[19], "unknown field 'render.k19' ignored");
  EXPECT_EQ(read.warnings[20], "and 880 more unknown fields ignored");
}

TEST(SessionHostile, ErrorsShowNoRawBytes) {
  // Invalid UTF-8 in a string: the JSON library's message quotes the bytes it read.
  const std::string bad = readTextError("{\"voxray-session\": 1, \"layout\": \"\xff\xfe\"}");
  EXPECT_NE(bad.find("s.json: not a JSON file"), std::string::npos) << bad;
  EXPECT_TRUE(validUtf8(bad)) << bad;
  EXPECT_NE(bad.find("\xEF\xBF\xBD"), std::string::npos) << bad;  // U+FFFD in their place
  // A terminal escape in a value shows as \u001b, not as the control character.
  Json j = Json::parse(sessionToJson(Session{}, "s.json"));
  j["render"]["azimuth"] = "left\x1b[31m";
  const std::string escape = readTextError(j.dump());
  EXPECT_NE(escape.find("field 'render.azimuth' is wrong: --azimuth: 'left\\u001b[31m' is not a "
                        "number"),
            std::string::npos)
      << escape;
  EXPECT_EQ(escape.find('\x1b'), std::string::npos);
  // So does one in an unknown field's name.
  j = Json::parse(sessionToJson(Session{}, "s.json"));
  j["slices"]["ruler\x1b[2J"] = 1;
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_EQ(read.warnings[0], "unknown field 'slices.ruler\\u001b[2J' ignored");
}

}  // namespace
