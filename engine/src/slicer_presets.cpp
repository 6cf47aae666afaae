// 3D Slicer's preset list (presets.xml, as its VolumeRendering module ships it): one
// <VolumeProperty> element per preset, its attributes the fields of a .vp file.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <tinyxml2.h>

#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The presets a list may hold: Slicer ships about 25.
constexpr size_t kMaxPresets = 1000;

}  // namespace

std::vector<VolumeProperty> parseSlicerPresets(const std::string& xml, const std::string& origin) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw inputError(origin + ": not valid XML (" + std::string(doc.ErrorStr()) + ")");
  const tinyxml2::XMLElement* list = doc.RootElement();
  std::vector<VolumeProperty> out;
  for (const tinyxml2::XMLElement* e = list ? list->FirstChildElement("VolumeProperty") : nullptr;
       e; e = e->NextSiblingElement("VolumeProperty")) {
    if (out.size() == kMaxPresets)
      throw inputError(origin + ": more than " + std::to_string(kMaxPresets) +
                       " presets; this is not a preset list");
    const char* name = e->Attribute("name");
    std::string which =
        origin + ", preset " +
        (name ? std::string("'") + name + "'" : "#" + std::to_string(out.size() + 1));
    // In the order of a .vp file, whose reader then checks every number.
    std::string vp;
    for (const char* key : {"interpolation", "shade", "diffuse", "ambient", "specular",
                            "specularPower", "scalarOpacity", "gradientOpacity", "colorTransfer"}) {
      const char* value = e->Attribute(key);
      if (!value) throw inputError(which + ": the attribute '" + key + "' is missing");
      vp += std::string(value) + "\n";
    }
    VolumeProperty p = parseSlicerVolumeProperty(vp, which);
    p.name = name ? name : "preset " + std::to_string(out.size() + 1);
    out.push_back(std::move(p));
  }
  if (out.empty())
    throw inputError(origin +
                     ": no <VolumeProperty> presets in it; 3D Slicer's list is "
                     "<PresetList><VolumeProperty name=... /></PresetList>");
  return out;
}

std::vector<VolumeProperty> readSlicerPresetFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw inputError(path + ": cannot open the preset list; check the path");
  // Asked before reading it: Slicer's own list is about 30 kB.
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > (std::uintmax_t(64) << 20) && !ec)
    throw inputError(path + ": over 64 MB, too large for a preset list");
  std::ostringstream text;
  text << in.rdbuf();
  return parseSlicerPresets(text.str(), path);
}

const VolumeProperty& findProperty(const std::vector<VolumeProperty>& presets,
                                   const std::string& name, const std::string& origin) {
  std::string known;
  for (const VolumeProperty& p : presets) {
    if (lower(p.name) == lower(name)) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw inputError(origin + ": no preset named '" + name + "'; it has " + known);
}

}  // namespace voxray
