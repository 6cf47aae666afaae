#pragma once
// Small parsers for parameter text ("1.5", "1,2,3"), throwing Error (Input) that names
// the parameter, so a typo on the command line says which flag is wrong.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace voxray::text {

double toDouble(const std::string& key, const std::string& s);
int toInt(const std::string& key, const std::string& s);
bool toBool(const std::string& key, const std::string& s);
std::vector<double> toDoubles(const std::string& key, const std::string& s, size_t minCount,
                              size_t maxCount);
std::vector<int> toInts(const std::string& key, const std::string& s, size_t minCount,
                        size_t maxCount);
glm::dvec3 toVec3(const std::string& key, const std::string& s);
std::string fmt(double v);
std::string fmt(const glm::dvec3& v);

}  // namespace voxray::text
