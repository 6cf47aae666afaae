// 3D Slicer's .seg.nrrd through Teem (libteem), as io's NRRD reader. The keys are those of
// Slicer's documented format (Developer Guide, "Segmentation labelmap file format").
#include <teem/nrrd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

#include "formats.h"
#include "teem_handles.h"
#include "voxray/io/error.h"

namespace voxray::segfiles {
namespace {

using teem::IoNix;
using teem::NrrdNix;
using teem::NrrdNuke;
using teem::reason;

// Header values are one line, and Slicer splits tags at | ~ ^.
std::string headerText(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '|' || c == '~' || c == '^') c = ' ';
  return s;
}

std::string codeText(const Segment::Code& c) {
  return headerText(c.scheme) + "^" + headerText(c.value) + "^" + headerText(c.meaning);
}

Segment::Code parseCode(const std::string& text) {
  Segment::Code c;
  std::istringstream in(text);
  std::getline(in, c.scheme, '^');
  std::getline(in, c.value, '^');
  std::getline(in, c.meaning);
  return c;
}

// Slicer's TerminologyEntry: context~category~type~type modifier~anatomic context~region~
// region modifier, each code scheme^value^meaning.
std::string terminologyTag(const Segment& s) {
  return "TerminologyEntry:Segmentation category and type - 3D Slicer General Anatomy list~" +
         codeText(s.category) + "~" + codeText(s.type) +
         "~^^~Anatomic codes - DICOM master list~^^~^^|";
}

void parseTerminology(const std::string& tags, Segment& s) {
  const std::string key = "TerminologyEntry:";
  const size_t at = tags.find(key);
  if (at == std::string::npos) return;
  std::string entry = tags.substr(at + key.size());
  entry = entry.substr(0, entry.find('|'));
  std::vector<std::string> parts;
  std::istringstream in(entry);
  for (std::string part; std::getline(in, part, '~');) parts.push_back(part);
  if (parts.size() >= 3) {
    s.category = parseCode(parts[1]);
    s.type = parseCode(parts[2]);
  }
}

// Each label's voxel box as Slicer writes it ("i0 i1 j0 j1 k0 k1", inclusive), one pass.
std::array<std::string, 256> extents(const Segmentation& seg) {
  std::array<glm::ivec3, 256> lo, hi;
  lo.fill(glm::ivec3(INT32_MAX));
  hi.fill(glm::ivec3(-1));
  const glm::ivec3 d = seg.grid.dims;
  size_t i = 0;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x, ++i) {
        const uint8_t l = seg.labels[i];
        if (l == 0) continue;
        lo[l] = glm::min(lo[l], glm::ivec3(x, y, z));
        hi[l] = glm::max(hi[l], glm::ivec3(x, y, z));
      }
  std::array<std::string, 256> out;
  for (size_t l = 0; l < 256; ++l) {
    if (hi[l].x < 0) {
      out[l] = "0 -1 0 -1 0 -1";  // Slicer's empty extent
      continue;
    }
    std::ostringstream s;
    s << lo[l].x << " " << hi[l].x << " " << lo[l].y << " " << hi[l].y << " " << lo[l].z << " "
      << hi[l].z;
    out[l] = s.str();
  }
  return out;
}

void addKey(Nrrd* n, const std::string& key, const std::string& value) {
  if (nrrdKeyValueAdd(n, key.c_str(), value.c_str()) != 0)
    throw outputError("NRRD header key " + key + ": " + reason());
}

std::string key(const Nrrd& n, const std::string& k) {
  char* v = nrrdKeyValueGet(&n, k.c_str());
  std::string s = v ? v : "";
  std::free(v);
  return s;
}

bool hasKey(const Nrrd& n, const std::string& k) {
  char* v = nrrdKeyValueGet(&n, k.c_str());
  const bool has = v != nullptr;
  std::free(v);
  return has;
}

glm::dvec3 lpsSigns(int space) {
  switch (space) {
    case nrrdSpaceRightAnteriorSuperior:
      return {-1, -1, 1};
    case nrrdSpaceLeftAnteriorSuperior:
      return {1, -1, 1};
    case nrrdSpaceLeftPosteriorSuperior:
      return {1, 1, 1};
    default:
      return {0, 0, 0};
  }
}

template <typename T>
void copyNrrdLabels(const Nrrd& n, LabelFile& out, const std::string& path) {
  const T* v = static_cast<const T*>(n.data);
  for (size_t i = 0; i < out.labels.size(); ++i) {
    const double value = double(v[i]);  // integer types only: whole numbers
    if (value < 0 || value > 255) throw inputError(labelValueProblem(value, path));
    out.labels[i] = uint8_t(v[i]);
  }
}

}  // namespace

void writeNrrd(const std::string& temporary, const Segmentation& seg) {
  const VoxelGrid& g = seg.grid;
  std::unique_ptr<Nrrd, NrrdNix> n(nrrdNew());
  size_t sizes[3] = {size_t(g.dims.x), size_t(g.dims.y), size_t(g.dims.z)};
  if (nrrdWrap_nva(n.get(), const_cast<uint8_t*>(seg.labels.data()), nrrdTypeUChar, 3, sizes))
    throw outputError(temporary + ": " + reason());
  nrrdSpaceSet(n.get(), nrrdSpaceLeftPosteriorSuperior);
  const double origin[3] = {g.originMm.x, g.originMm.y, g.originMm.z};
  nrrdSpaceOriginSet(n.get(), origin);
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned r = 0; r < 3; ++r)
      n->axis[a].spaceDirection[r] = g.direction[int(a)][int(r)] * g.spacingMm[int(a)];
    n->axis[a].kind = nrrdKindDomain;
  }
  addKey(n.get(), "Segmentation_MasterRepresentation", "Binary labelmap");
  addKey(n.get(), "Segmentation_ContainedRepresentationNames", "Binary labelmap|");
  addKey(n.get(), "Segmentation_ReferenceImageExtentOffset", "0 0 0");
  const std::array<std::string, 256> boxes = extents(seg);
  for (size_t i = 0; i < seg.segments.size(); ++i) {
    const Segment& s = seg.segments[i];
    const std::string p = "Segment" + std::to_string(i) + "_";
    char colour[64];
    std::snprintf(colour, sizeof colour, "%.6g %.6g %.6g", double(s.colour.r), double(s.colour.g),
                  double(s.colour.b));
    addKey(n.get(), p + "Color", colour);
    addKey(n.get(), p + "ColorAutoGenerated", "0");
    addKey(n.get(), p + "Extent", boxes[s.label]);
    addKey(n.get(), p + "ID", "Segment_" + std::to_string(s.label));
    addKey(n.get(), p + "LabelValue", std::to_string(s.label));
    addKey(n.get(), p + "Layer", "0");
    addKey(n.get(), p + "Name", headerText(s.name));
    addKey(n.get(), p + "NameAutoGenerated", "0");
    addKey(n.get(), p + "Tags", terminologyTag(s));
  }
  std::unique_ptr<NrrdIoState, IoNix> io(nrrdIoStateNew());
  // Slicer's own files are gzip; a Teem built without zlib writes raw, still valid NRRD.
  if (nrrdEncodingGzip->available()) {
    io->encoding = nrrdEncodingGzip;
    io->zlibLevel = 6;  // zlib's default: most of the gain, a fraction of level 9's time
  }
  if (nrrdSave(temporary.c_str(), n.get(), io.get()) != 0)
    throw outputError(temporary + ": " + reason());
}

LabelFile readNrrd(const std::string& path) {
  std::unique_ptr<Nrrd, NrrdNuke> n(nrrdNew());
  if (nrrdLoad(n.get(), path.c_str(), nullptr) != 0)
    throw inputError(path + ": cannot be read as NRRD (" + reason() + ")");
  if (n->dim != 3)
    throw inputError(path + ": has " + std::to_string(n->dim) +
                     " axes; Voxray reads 3D label maps (a .seg.nrrd with overlapping segments "
                     "has layers: in Slicer, export it as a labelmap first)");
  const glm::dvec3 signs = lpsSigns(n->space);
  if (signs == glm::dvec3(0.0))
    throw inputError(path +
                     ": its space is not anatomical (LPS, RAS or LAS), so where its "
                     "voxels lie is unknown");
  LabelFile out;
  out.grid.dims = {int(n->axis[0].size), int(n->axis[1].size), int(n->axis[2].size)};
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 step;
    for (int r = 0; r < 3; ++r) step[r] = signs[r] * n->axis[a].spaceDirection[r];
    if (!std::isfinite(step.x) || glm::length(step) <= 0)
      throw inputError(path + ": axis " + std::to_string(a) + " has no space direction");
    out.grid.spacingMm[a] = glm::length(step);
    out.grid.direction[a] = step / out.grid.spacingMm[a];
  }
  for (int r = 0; r < 3; ++r)
    out.grid.originMm[r] = std::isfinite(n->spaceOrigin[r]) ? signs[r] * n->spaceOrigin[r] : 0.0;
  out.labels.resize(out.grid.voxelCount());
  switch (n->type) {
    case nrrdTypeUChar:
      copyNrrdLabels<uint8_t>(*n, out, path);
      break;
    case nrrdTypeChar:
      copyNrrdLabels<int8_t>(*n, out, path);
      break;
    case nrrdTypeShort:
      copyNrrdLabels<int16_t>(*n, out, path);
      break;
    case nrrdTypeUShort:
      copyNrrdLabels<uint16_t>(*n, out, path);
      break;
    case nrrdTypeInt:
      copyNrrdLabels<int32_t>(*n, out, path);
      break;
    case nrrdTypeUInt:
      copyNrrdLabels<uint32_t>(*n, out, path);
      break;
    default:
      throw inputError(path + ": holds " + airEnumStr(nrrdType, n->type) +
                       " values; a label map holds whole numbers 0 to 255");
  }
  for (int i = 0; hasKey(*n, "Segment" + std::to_string(i) + "_ID") ||
                  hasKey(*n, "Segment" + std::to_string(i) + "_Name");
       ++i) {
    const std::string p = "Segment" + std::to_string(i) + "_";
    Segment s;
    s.name = key(*n, p + "Name");
    if (hasKey(*n, p + "Layer") && std::atoi(key(*n, p + "Layer").c_str()) != 0)
      throw inputError(path + ": segment \"" + s.name +
                       "\" lies in another layer (segments "
                       "overlap); Voxray keeps one label per voxel: export a labelmap from Slicer");
    const int label = hasKey(*n, p + "LabelValue") ? std::atoi(key(*n, p + "LabelValue").c_str())
                                                   : i + 1;  // files before LabelValue
    if (label < 1 || label > 255)
      throw inputError(path + ": segment \"" + s.name + "\" has label value " +
                       std::to_string(label) + "; label values are 1 to 255");
    s.label = uint8_t(label);
    std::istringstream colour(key(*n, p + "Color"));
    float r = 0, g = 0, b = 0;
    if (colour >> r >> g >> b) s.colour = {r, g, b};
    parseTerminology(key(*n, p + "Tags"), s);
    out.segments.push_back(s);
  }
  return out;
}

}  // namespace voxray::segfiles
