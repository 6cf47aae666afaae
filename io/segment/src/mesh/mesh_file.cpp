#include "voxray/io/mesh_file.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <unistd.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/segmentation_check.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

std::string frameName(MeshCoordinates c) { return c == MeshCoordinates::Lps ? "LPS" : "RAS"; }

// Hidden beside the target (same file system, so the rename is atomic), extension kept.
fs::path temporaryBeside(const fs::path& target) {
  static std::atomic<int> counter{0};
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(getpid()) + "-" + std::to_string(counter++);
  name += target.extension().string();
  return target.parent_path() / name;
}

struct Part {
  const Segment* segment;
  SegmentSurface surface;
};

// The parts' vertices in the file's frame; RAS turns LPS half a turn about z (x and y
// negated), a rotation, so the triangles keep facing outwards.
glm::vec3 framed(const glm::vec3& lps, MeshCoordinates c) {
  return c == MeshCoordinates::Lps ? lps : glm::vec3(-lps.x, -lps.y, lps.z);
}

vtkSmartPointer<vtkPolyData> polyOfParts(const std::vector<const Part*>& parts, MeshCoordinates c) {
  size_t nv = 0, nt = 0;
  for (const Part* p : parts) nv += p->surface.vertices.size(), nt += p->surface.triangleCount();
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(vtkIdType(nv));
  vtkNew<vtkTypeInt64Array> connectivity, offsets;
  connectivity->SetNumberOfValues(vtkIdType(nt * 3));
  offsets->SetNumberOfValues(vtkIdType(nt + 1));
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(vtkIdType(nt));
  float* v = xyz->GetPointer(0);
  vtkTypeInt64* ids = connectivity->GetPointer(0);
  unsigned char* colour = rgb->GetPointer(0);
  size_t base = 0, t = 0;
  for (const Part* p : parts) {
    for (const auto& q : p->surface.vertices) {
      const glm::vec3 f = framed(q, c);
      *v++ = f.x, *v++ = f.y, *v++ = f.z;
    }
    const glm::vec3 c8 = glm::round(glm::clamp(p->segment->colour, 0.0f, 1.0f) * 255.0f);
    for (size_t i = 0; i < p->surface.indices.size(); i += 3, ++t) {
      for (int k = 0; k < 3; ++k) *ids++ = vtkTypeInt64(base + p->surface.indices[i + k]);
      *colour++ = (unsigned char)c8.r, *colour++ = (unsigned char)c8.g,
      *colour++ = (unsigned char)c8.b;
    }
    base += p->surface.vertices.size();
  }
  for (size_t i = 0; i <= nt; ++i) offsets->SetValue(vtkIdType(i), vtkTypeInt64(3 * i));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetCellData()->AddArray(rgb);
  return poly;
}

std::string segmentList(const std::vector<const Part*>& parts) {
  std::string names;
  for (const Part* p : parts) names += (names.empty() ? "" : ", ") + p->segment->name;
  return names;
}

void writeStl(const fs::path& file, const std::vector<const Part*>& parts, MeshCoordinates c) {
  vtkNew<vtkSTLWriter> writer;
  writer->SetInputData(polyOfParts(parts, c));
  writer->SetFileName(file.c_str());
  writer->SetFileTypeToBinary();
  // A binary STL's 80-byte header is its only free text: the frame first, so it survives.
  const std::string header = "Voxray mesh, " + frameName(c) + " mm: " + segmentList(parts);
  writer->SetHeader(header.substr(0, 80).c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
    throw outputError("Could not write the STL file " + file.string() + ".");
}

void writePly(const fs::path& file, const std::vector<const Part*>& parts, MeshCoordinates c) {
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(polyOfParts(parts, c));
  writer->SetFileName(file.c_str());
  writer->SetFileTypeToBinary();
  writer->SetArrayName("RGB");  // each face in its segment's colour
  writer->SetColorModeToDefault();
  writer->AddComment("Voxray segment mesh");
  writer->AddComment("coordinates: " + frameName(c) + " millimetres");
  writer->AddComment("segments: " + segmentList(parts));
  writer->Write();
  if (writer->GetErrorCode() != 0)
    throw outputError("Could not write the PLY file " + file.string() + ".");
}

std::string materialName(const Segment& s) {
  std::string name = "segment_" + std::to_string(s.label);
  for (char c : s.name)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') name += c;
  return name;
}

struct File {
  std::FILE* f = nullptr;
  fs::path path;
  explicit File(const fs::path& p) : f(std::fopen(p.c_str(), "wb")), path(p) {
    if (!f)
      throw outputError("Could not create " + p.string() +
                        ": check the folder exists and is writable.");
  }
  ~File() {
    if (f) std::fclose(f);
  }
  void close() {
    const bool failed = std::ferror(f) != 0;
    const bool closeFailed = std::fclose(f) != 0;
    f = nullptr;
    if (failed || closeFailed)
      throw outputError("Could not write " + path.string() + " (disk full?).");
  }
};

// OBJ and MTL by hand: plain text that VTK's OBJ exporter only writes from a render window.
void writeObj(const fs::path& file, const fs::path& mtlFile, const std::string& mtlName,
              const std::vector<const Part*>& parts, MeshCoordinates c) {
  File mtl(mtlFile);
  std::fprintf(mtl.f, "# Voxray segment colours (sRGB)\n");
  for (const Part* p : parts) {
    const Segment& s = *p->segment;
    std::fprintf(mtl.f, "newmtl %s\nKa 0 0 0\nKd %.4f %.4f %.4f\nKs 0 0 0\nd %.4f\nillum 1\n\n",
                 materialName(s).c_str(), s.colour.r, s.colour.g, s.colour.b, s.opacity);
  }
  mtl.close();
  File obj(file);
  std::fprintf(obj.f, "# Voxray segment mesh\n# coordinates: %s millimetres\nmtllib %s\n",
               frameName(c).c_str(), mtlName.c_str());
  size_t base = 1;
  for (const Part* p : parts) {
    std::fprintf(obj.f, "o %s\nusemtl %s\n", materialName(*p->segment).c_str(),
                 materialName(*p->segment).c_str());
    for (const auto& q : p->surface.vertices) {
      const glm::vec3 f = framed(q, c);
      std::fprintf(obj.f, "v %.4f %.4f %.4f\n", f.x, f.y, f.z);
    }
    const auto& ix = p->surface.indices;
    for (size_t i = 0; i < ix.size(); i += 3)
      std::fprintf(obj.f, "f %zu %zu %zu\n", base + ix[i], base + ix[i + 1], base + ix[i + 2]);
    base += p->surface.vertices.size();
  }
  obj.close();
}

}  // namespace

void writeMeshFile(const std::string& path, const Segmentation& s,
                   const std::vector<uint8_t>& labels, const MeshFileOptions& options) {
  const MeshFormat format = meshFormatFor(path);
  checkSegmentation(s);
  std::vector<Part> parts;
  if (labels.empty()) {
    for (const auto& seg : s.segments)
      if (seg.visible && std::find(s.labels.begin(), s.labels.end(), seg.label) != s.labels.end())
        parts.push_back({&seg, {}});
    if (parts.empty())
      throw inputError("No visible segment has voxels, so there is no surface to write to " + path +
                       ": show a segment or paint one first.");
  } else {
    for (uint8_t label : labels) {
      const Segment* seg = s.find(label);
      if (!seg)
        throw inputError("No segment has label " + std::to_string(label) +
                         ": choose one of the segmentation's segments to export.");
      parts.push_back({seg, {}});
    }
  }

  // Every target, checked before any work, so that a refusal leaves everything as it was.
  struct Target {
    fs::path file, mtl;
    std::vector<const Part*> parts;
  };
  std::vector<Target> targets;
  const auto mtlOf = [&](const fs::path& f) {
    return format == MeshFormat::Obj ? fs::path(f).replace_extension(".mtl") : fs::path();
  };
  if (options.perSegment) {
    for (const auto& p : parts) {
      const fs::path f = perSegmentPath(path, *p.segment);
      targets.push_back({f, mtlOf(f), {&p}});
    }
  } else {
    Target t{path, mtlOf(path), {}};
    for (const auto& p : parts) t.parts.push_back(&p);
    targets.push_back(t);
  }
  for (const auto& t : targets) {
    const fs::path folder = t.file.parent_path().empty() ? fs::path(".") : t.file.parent_path();
    if (!fs::is_directory(folder))
      throw inputError("The folder " + folder.string() +
                       " does not exist: create it or choose another.");
    for (const fs::path& f : {t.file, t.mtl})
      if (!f.empty() && fs::exists(f) && !options.overwrite)
        throw inputError(f.string() +
                         " exists already: choose another name, or allow overwriting.");
  }

  // One segment per core: flying edges and smoothing are threaded (vtkSMPTools) but the
  // crop, the slabs' seams and the writing are not. The error of the first segment that
  // fails is the one reported, as a serial loop would.
  parallelFor(parts.size(), [&](size_t i) {
    parts[i].surface = makeSurface(s, parts[i].segment->label, options.surface);
  });

  std::vector<std::pair<fs::path, fs::path>> written;  // temporary -> final
  try {
    for (const auto& t : targets) {
      const fs::path tmp = temporaryBeside(t.file);
      written.push_back({tmp, t.file});
      switch (format) {
        case MeshFormat::Stl:
          writeStl(tmp, t.parts, options.coordinates);
          break;
        case MeshFormat::Ply:
          writePly(tmp, t.parts, options.coordinates);
          break;
        case MeshFormat::Obj: {
          const fs::path mtlTmp = temporaryBeside(t.mtl);
          written.push_back({mtlTmp, t.mtl});
          writeObj(tmp, mtlTmp, t.mtl.filename().string(), t.parts, options.coordinates);
          break;
        }
      }
    }
    for (const auto& [tmp, final] : written) fs::rename(tmp, final);
  } catch (const std::filesystem::filesystem_error& e) {
    for (const auto& w : written) fs::remove(w.first);
    throw outputError(std::string("Could not write the mesh file: ") + e.what());
  } catch (...) {
    std::error_code ignored;
    for (const auto& w : written) fs::remove(w.first, ignored);
    throw;
  }
}

}  // namespace voxray
