#include "text_parse.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "voxray/io/error.h"

namespace voxray::text {

double toDouble(const std::string& key, const std::string& s) {
  double v = 0.0;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v))
    throw inputError("--" + key + ": '" + s + "' is not a number");
  return v;
}

int toInt(const std::string& key, const std::string& s) {
  int v = 0;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, v);
  if (ec != std::errc() || ptr != end)
    throw inputError("--" + key + ": '" + s + "' is not a whole number");
  return v;
}

bool toBool(const std::string& key, const std::string& s) {
  if (s == "1" || s == "on" || s == "true" || s == "yes") return true;
  if (s == "0" || s == "off" || s == "false" || s == "no") return false;
  throw inputError("--" + key + ": '" + s + "' is not on/off");
}

namespace {

// The comma-separated items of S, MIN_COUNT to MAX_COUNT of them, each read by READ.
template <class T, class Read>
std::vector<T> toList(const std::string& key, const std::string& s, size_t minCount,
                      size_t maxCount, Read read) {
  std::vector<T> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(read(key, item));
  if (out.size() < minCount || out.size() > maxCount) {
    std::string want = minCount == maxCount
                           ? std::to_string(minCount)
                           : std::to_string(minCount) + " to " + std::to_string(maxCount);
    throw inputError("--" + key + ": expected " + want + " comma-separated numbers, got '" + s +
                     "'");
  }
  return out;
}

}  // namespace

std::vector<double> toDoubles(const std::string& key, const std::string& s, size_t minCount,
                              size_t maxCount) {
  return toList<double>(key, s, minCount, maxCount, toDouble);
}

std::vector<int> toInts(const std::string& key, const std::string& s, size_t minCount,
                        size_t maxCount) {
  return toList<int>(key, s, minCount, maxCount, toInt);
}

glm::dvec3 toVec3(const std::string& key, const std::string& s) {
  auto v = toDoubles(key, s, 3, 3);
  return {v[0], v[1], v[2]};
}

// The shortest text that reads back as exactly V: saved state (a session) must reproduce
// the frame it was saved from bit for bit, and a camera dragged to 31.23456789012 degrees
// would not survive ten digits.
std::string fmt(double v) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
}

std::string fmt(const glm::dvec3& v) { return fmt(v.x) + "," + fmt(v.y) + "," + fmt(v.z); }

}  // namespace voxray::text
