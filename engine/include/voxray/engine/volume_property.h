#pragma once
// A transfer function as users shape it (issue 35): colour points and opacity points in two
// independent lists, as VTK's vtkVolumeProperty and 3D Slicer keep them, linear or smooth
// between points, opacity stated per unit distance, an optional gradient-magnitude opacity and
// the shading coefficients. It becomes a render table (RenderParams::transferFunction) with
// applyVolumeProperty; its files are Voxray's JSON and Slicer's volume-property text (.vp).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/tf2d.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {

struct RenderParams;

// Between points: straight lines, or a monotone cubic (Fritsch-Carlson), which is smooth at
// the points and never overshoots them, so an opacity stays within its neighbours' range.
enum class TfCurve { Linear, Smooth };

struct ColorNode {
  double hu = 0.0;
  glm::dvec3 rgb{0.0};  // 0 ... 1
  bool operator==(const ColorNode&) const = default;
};

struct OpacityNode {
  double x = 0.0;        // HU for the scalar opacity, HU/mm for the gradient-magnitude opacity
  double opacity = 0.0;  // 0 ... 1
  bool operator==(const OpacityNode&) const = default;
};

struct VolumeProperty {
  std::string name;
  std::vector<ColorNode> color;              // sorted by HU; a repeated HU makes a step
  std::vector<OpacityNode> opacity;          // sorted by HU; a repeated HU makes a step
  std::vector<OpacityNode> gradientOpacity;  // over |gradient| in HU/mm; empty = 1 everywhere
  // The 2D transfer function (tf2d.h), optional: when set, dvr takes colour and opacity from it
  // instead of the lists above. Voxray's JSON keeps it ("tf2d"); a .vp file has no place for it.
  Tf2d tf2d;
  TfCurve curve = TfCurve::Linear;
  // The ray length (mm) over which a stated opacity holds (VTK's scalar opacity unit
  // distance); 0 = the volume's smallest voxel spacing, the meaning Voxray's presets have.
  double unitDistanceMm = 0.0;
  bool shade = true;
  bool nearest = false;  // nearest-neighbour sampling instead of trilinear
  double ambient = 0.15, diffuse = 0.75, specular = 0.25, specularPower = 32.0;
  bool operator==(const VolumeProperty&) const = default;
};

// The most points one list may have: far more than any editor makes, few enough that a
// hostile file cannot make the table costly.
inline constexpr size_t kMaxTfPoints = 4096;

// Throws Error (Input) naming ORIGIN and the field that is wrong: an empty colour or opacity
// list, a count over kMaxTfPoints, a value that is not finite, a colour or opacity outside
// 0 ... 1, unsorted points, a negative unit distance or shading coefficient.
void validate(const VolumeProperty& vp, const std::string& origin);

// Values between points by the property's curve, constant beyond the ends.
glm::dvec3 colorAt(const VolumeProperty& vp, double hu);
double opacityAt(const VolumeProperty& vp, double hu);  // per unit distance
double gradientOpacityAt(const VolumeProperty& vp, double gradientMagnitude);

// True when the gradient-magnitude opacity changes anything (some point below 1).
bool hasGradientOpacity(const VolumeProperty& vp);

// The render table: colour and opacity at every point of either list, and for a smooth curve
// enough points between them that straight lines stay within 1/1024 of the curve. Opacity
// stays per unit distance (RenderParams::opacityUnitMm says which).
std::vector<ControlPoint> renderTable(const VolumeProperty& vp);

// What the renderer takes from VP: the table (replacing a preset), its unit distance,
// shading and its coefficients, the sampling; the mode becomes dvr.
void applyVolumeProperty(RenderParams& p, const VolumeProperty& vp);

// A render table read back as a property: colour and opacity at the table's points, linear.
// With applyVolumeProperty this is exact for a linear property whose two lists share their HUs.
VolumeProperty volumePropertyOf(const RenderParams& p);

// Voxray's own file (JSON, "format": "voxray-transfer-function", "version": 1).
VolumeProperty parseVolumePropertyJson(const std::string& text, const std::string& origin);
std::string toVolumePropertyJson(const VolumeProperty& vp);

// 3D Slicer's volume-property text (.vp): interpolation, shade, diffuse, ambient, specular,
// specular power, then the scalar opacity, gradient opacity and colour functions, each as a
// count of numbers followed by the numbers. It has no curve, unit distance or name: a smooth
// curve is written as its render table.
VolumeProperty parseSlicerVolumeProperty(const std::string& text, const std::string& origin);
std::string toSlicerVolumeProperty(const VolumeProperty& vp);

// 3D Slicer's preset list (presets.xml): each <VolumeProperty> element's attributes hold the
// same fields as a .vp file (name, interpolation, shade, ambient, diffuse, specular,
// specularPower, scalarOpacity, gradientOpacity, colorTransfer). Throws Error (Input) naming
// the preset and the attribute that is missing or wrong.
std::vector<VolumeProperty> parseSlicerPresets(const std::string& xml, const std::string& origin);
std::vector<VolumeProperty> readSlicerPresetFile(const std::string& path);
// The preset named NAME (case-insensitive) of PRESETS; throws Error (Input) listing the names.
const VolumeProperty& findProperty(const std::vector<VolumeProperty>& presets,
                                   const std::string& name, const std::string& origin);

// By the file's extension (.json or .vp); throws Error (Input) for another or a bad file.
VolumeProperty readVolumePropertyFile(const std::string& path);
// Throws Error (Output) when the file cannot be written.
void writeVolumePropertyFile(const VolumeProperty& vp, const std::string& path);

}  // namespace voxray
