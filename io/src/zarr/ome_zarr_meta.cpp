#include "ome_zarr_meta.h"

#include <cmath>
#include <cstdint>

#include "voxray/io/error.h"
#include "zarr_array.h"

namespace voxray::zarr {
namespace {

using Json = nlohmann::json;

[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw inputError(file + ": " + what);
}

// Millimetres per UNIT (NGFF takes UDUNITS-2 names); 0 when it is not a length.
double mmPer(const std::string& unit) {
  static const std::pair<const char*, double> units[] = {
      {"angstrom", 1e-7},   {"nanometer", 1e-6},  {"micrometer", 1e-3}, {"millimeter", 1.0},
      {"centimeter", 10.0}, {"decimeter", 100.0}, {"meter", 1000.0}};
  for (const auto& [name, mm] : units)
    if (unit == name) return mm;
  return 0.0;
}

// The scale and translation of one coordinateTransformations list (missing: 1 and 0).
void transformsOf(const std::string& file, const Json& list, size_t n, std::vector<double>& scale,
                  std::vector<double>& translation) {
  scale.assign(n, 1.0);
  translation.assign(n, 0.0);
  if (list.is_null()) return;
  if (!list.is_array()) bad(file, "coordinateTransformations is not a list");
  for (const Json& t : list) {
    const std::string type = t.is_object() ? t.value("type", "") : "";
    if (type == "identity") continue;
    if (type != "scale" && type != "translation")
      bad(file, "the coordinate transformation " + t.dump() +
                    " is not one NGFF 0.4/0.5 allows (scale, translation)");
    if (t.contains("path"))
      bad(file, "the " + type + " is stored in a file (\"path\"); Voxray reads it inline only");
    const Json& values = t.contains(type) ? t[type] : Json();
    if (!values.is_array() || values.size() != n)
      bad(file, "the " + type + " " + values.dump() + " does not give one number per axis (" +
                    std::to_string(n) + ")");
    for (size_t a = 0; a < n; ++a) {
      if (!values[a].is_number() || !std::isfinite(values[a].get<double>()))
        bad(file, "the " + type + " " + values.dump() + " holds something that is not a number");
      (type == "scale" ? scale : translation)[a] = values[a].get<double>();
    }
  }
}

glm::dmat3 directionOf(const std::string& file, const Json& d) {
  if (!d.is_array() || d.size() != 3) bad(file, "voxray.direction is not 3 columns of 3 numbers");
  glm::dmat3 m(1.0);
  for (int c = 0; c < 3; ++c) {
    if (!d[c].is_array() || d[c].size() != 3)
      bad(file, "voxray.direction is not 3 columns of 3 numbers");
    for (int r = 0; r < 3; ++r) {
      if (!d[c][r].is_number()) bad(file, "voxray.direction holds something that is not a number");
      m[c][r] = d[c][r].get<double>();
    }
    const double length = glm::length(m[c]);
    if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-3)
      bad(file, "voxray.direction's column " + std::to_string(c) + " is not a unit vector");
  }
  if (std::abs(glm::determinant(m)) < 1e-3) bad(file, "voxray.direction's axes are parallel");
  return m;
}

}  // namespace

std::string kindName(detail::SampleKind kind) {
  static const char* const names[] = {"u8", "i8", "u16", "i16", "u32", "i32", "f32", "f64"};
  return names[int(kind)];
}

Pyramid readPyramid(ZarrStore& store) {
  std::vector<uint8_t> bytes;
  if (readMetadata(store, "zarr.json", bytes))
    return parsePyramid(3, parseJson(bytes, store.where("zarr.json")), store.where("zarr.json"));
  if (readMetadata(store, ".zattrs", bytes))
    return parsePyramid(2, parseJson(bytes, store.where(".zattrs")), store.where(".zattrs"));
  // A group without attributes has no multiscales: said by parsePyramid.
  if (readMetadata(store, ".zgroup", bytes))
    return parsePyramid(2, Json::object(), store.where(".zattrs"));
  if (readMetadata(store, ".zarray", bytes))
    bad(store.where(""),
        "is a single Zarr array, not an OME-Zarr group; open the folder that holds it "
        "with its multiscales metadata");
  bad(store.where(""),
      "holds neither zarr.json (Zarr v3) nor .zattrs (Zarr v2): it is not an "
      "OME-Zarr folder");
}

Pyramid parsePyramid(int format, const Json& document, const std::string& file) {
  Pyramid p;
  p.format = format;
  Json attributes = document;
  if (format == 3) {
    const Json* zarrFormat = document.is_object() && document.contains("zarr_format")
                                 ? &document["zarr_format"]
                                 : nullptr;
    if (!zarrFormat || *zarrFormat != 3)
      bad(file, "zarr_format is not 3; the Zarr metadata is damaged");
    if (!document.contains("node_type") || document["node_type"] != "group")
      bad(file,
          "is a single array, not an OME-Zarr group; open the folder that holds it with "
          "its multiscales metadata");
    attributes = document.contains("attributes") ? document["attributes"] : Json::object();
  }
  if (!attributes.is_object()) bad(file, "the attributes are not a JSON object");
  // NGFF 0.5 keeps everything under "ome"; 0.4 at the top.
  const Json& ome = attributes.contains("ome") ? attributes["ome"] : attributes;
  if (!ome.is_object() || !ome.contains("multiscales") || !ome["multiscales"].is_array() ||
      ome["multiscales"].empty())
    bad(file,
        "has no OME-NGFF multiscales metadata; it is a plain Zarr group, not an OME-Zarr "
        "image (Voxray reads NGFF 0.4 and 0.5 images)");
  const Json& ms = ome["multiscales"][0];
  if (ome["multiscales"].size() > 1)
    p.warnings.push_back("the folder holds " + std::to_string(ome["multiscales"].size()) +
                         " images (multiscales); Voxray shows the first");
  try {
    const Json& axes = ms.at("axes");
    if (!axes.is_array()) bad(file, "multiscales axes is not a list");
    p.axes = axes.size();
    if (p.axes < 3 || p.axes > 5)
      bad(file, "the image has " + std::to_string(p.axes) +
                    " axes; Voxray opens 3D volumes (z, y, x, with up to 2 leading t, c axes)");
    std::vector<double> mm(p.axes, 1.0);
    for (size_t a = 0; a < p.axes; ++a) {
      const Json& axis = axes[a];
      const std::string name = axis.is_object()   ? axis.value("name", "")
                               : axis.is_string() ? axis.get<std::string>()
                                                  : "";
      const std::string type = axis.is_object() ? axis.value("type", "") : "";
      p.axisNames.push_back(name);
      if (a + 3 < p.axes) continue;
      if (!type.empty() && type != "space")
        bad(file, "the axis '" + name + "' is of type " + type +
                      "; Voxray needs the last three axes to be space (z, y, x)");
      const std::string unit = axis.is_object() ? axis.value("unit", "") : "";
      if (unit.empty()) {
        p.warnings.push_back("the axis '" + name + "' has no unit; millimetres are assumed");
      } else if ((mm[a] = mmPer(unit)) == 0.0) {
        bad(file, "the axis '" + name + "' has the unit '" + unit +
                      "', not a length Voxray knows (micrometer, millimeter, meter, ...)");
      }
    }
    std::vector<double> globalScale, globalTranslation;
    transformsOf(
        file, ms.contains("coordinateTransformations") ? ms["coordinateTransformations"] : Json(),
        p.axes, globalScale, globalTranslation);
    const Json& datasets = ms.at("datasets");
    if (!datasets.is_array() || datasets.empty()) bad(file, "multiscales has no datasets");
    for (const Json& d : datasets) {
      const std::string path = d.at("path").get<std::string>();
      if (path.empty() || path.find("..") != std::string::npos || path.front() == '/')
        bad(file, "the dataset path '" + path + "' leaves the folder");
      std::vector<double> scale, translation;
      transformsOf(
          file, d.contains("coordinateTransformations") ? d["coordinateTransformations"] : Json(),
          p.axes, scale, translation);
      Level level;
      level.path = path;
      for (int i = 0; i < 3; ++i) {
        const size_t a = p.axes - 1 - size_t(i);  // x is the last axis
        const double s = scale[a] * globalScale[a] * mm[a];
        if (!(s > 0.0) || !std::isfinite(s))
          bad(file, "the dataset '" + path + "' has the scale " + std::to_string(scale[a]) +
                        " along '" + p.axisNames[a] + "'; a voxel size must be positive");
        level.spacingMm[i] = s;
        level.translationMm[i] = (translation[a] * globalScale[a] + globalTranslation[a]) * mm[a];
        // Each number is finite; their product and sum may not be (1e300 x 1e300).
        if (!std::isfinite(level.translationMm[i]))
          bad(file, "the dataset '" + path + "' has a translation along '" + p.axisNames[a] +
                        "' beyond any length (its translation and scale multiply past 1e308 "
                        "mm); the metadata is damaged");
      }
      p.levels.push_back(level);
    }
  } catch (const Json::exception& e) {
    bad(file, std::string("the multiscales metadata is damaged (") + e.what() + ")");
  }
  if (attributes.contains(kVoxrayBlock) && attributes[kVoxrayBlock].is_object()) {
    const Json& v = attributes[kVoxrayBlock];
    if (v.contains("direction")) p.direction = directionOf(file, v["direction"]);
    if (v.contains("unit") && v["unit"].is_string()) p.unit = v["unit"].get<std::string>();
    if (v.contains("modality") && v["modality"].is_string())
      p.modality = v["modality"].get<std::string>();
    // A damaged range is left out and said: out-of-core rendering then finds it from the
    // voxels (it only spares that pass; never trusted over them: out_of_core.h).
    if (v.contains("level0-range")) {
      const Json& r = v["level0-range"];
      if (r.is_array() && r.size() == 2 && r[0].is_number_integer() && r[1].is_number_integer() &&
          r[0].get<int64_t>() >= INT16_MIN && r[1].get<int64_t>() <= INT16_MAX &&
          r[0].get<int64_t>() <= r[1].get<int64_t>())
        p.level0Range = ValueRange{int16_t(r[0].get<int64_t>()), int16_t(r[1].get<int64_t>())};
      else
        p.warnings.push_back("voxray.level0-range " + r.dump() +
                             " is not two whole numbers from -32768 to 32767, smallest first; "
                             "ignored (the range is found from the voxels)");
    }
  }
  return p;
}

}  // namespace voxray::zarr
