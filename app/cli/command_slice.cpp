// voxray-cli slice: one plane of the volume as the workstation's slice views show it (the
// same plane geometry, ui/study, and resampling, plane_sampler.h), thin or a slab.
#include <chrono>
#include <cmath>
#include <iostream>

#include "commands.h"
#include "input_options.h"
#include "mpr_planes.h"
#include "slice_image.h"
#include "study_state.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray::cli {

namespace {

struct SliceOptions {
  InputOptions input;
  std::string plane = "axial", slabMode = "mip", interp = "linear", output;
  int index = 0;
  double mm = 0.0;
  bool hasIndex = false, hasMm = false;  // given on the command line
  std::vector<double> normal, point, wl;
  double slabMm = 0.0;
};

Orientation parseOrientation(const std::string& s) {
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal})
    if (s == toString(o)) return o;
  throw inputError("--plane '" + s + "' is not one of axial, coronal, sagittal");
}

glm::dvec3 vec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// The view and crosshair (voxel coordinates) the options ask for.
struct Chosen {
  SliceAxes axes;
  glm::dvec3 centre;
  glm::dmat3 rotation{1.0};
};

Chosen choosePlane(const Volume& v, const SliceOptions& o) {
  Chosen c;
  c.centre = glm::round((glm::dvec3(v.dims) - 1.0) * 0.5);
  if (!o.point.empty()) c.centre = patientMmToVoxel(v, vec3(o.point));
  if (!o.normal.empty()) {
    const glm::dvec3 n = vec3(o.normal);
    if (!(glm::length(n) > 1e-9) || !std::isfinite(glm::length(n)))
      throw inputError("--normal must be a non-zero direction, e.g. 0,0.7071,0.7071");
    const ObliqueView view = viewForNormal(v.direction, n);
    c.axes = sliceAxes(v.direction, view.orientation);
    c.rotation = view.rotation;
  } else {
    c.axes = sliceAxes(v.direction, parseOrientation(o.plane));
    const int count = v.dims[c.axes.nAxis];
    if (o.hasIndex) {
      if (o.index < 0 || o.index >= count)
        throw inputError("--index " + std::to_string(o.index) + ": the " + o.plane +
                         " plane has slices 0 to " + std::to_string(count - 1));
      c.centre[c.axes.nAxis] = o.index;
    } else if (o.hasMm) {
      // On the positive LPS axis nearest the view's normal (axial: S, even for slices
      // stored head to feet), the plane whose points lie at o.mm.
      glm::dvec3 normal = v.direction[c.axes.nAxis];
      const glm::dvec3 size = glm::abs(normal);
      const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
      if (normal[axis] < 0) normal = -normal;
      const glm::dvec3 at = voxelToPatientMm(v, c.centre);
      c.centre = patientMmToVoxel(v, at + normal * (o.mm - glm::dot(normal, at)));
    }
  }
  return c;
}

}  // namespace

Run addSliceCommand(CLI::App& app) {
  auto o = std::make_shared<SliceOptions>();
  auto* cmd = app.add_subcommand(
      "slice", "Write one plane of a volume (axial, coronal, sagittal or oblique; thin or a slab)");
  o->input.add(*cmd);
  cmd->add_option("-o,--output", o->output, "image file to write (PNG, TIFF or EXR)")->required();
  auto* plane = cmd->add_option("--plane", o->plane, "axial, coronal or sagittal (default axial)");
  auto* index =
      cmd->add_option("--index", o->index, "slice number along the plane's normal, from 0");
  auto* mm = cmd->add_option("--mm", o->mm,
                             "position along the plane's normal in LPS mm (axial: S, coronal: "
                             "P, sagittal: L)");
  index->excludes(mm);
  auto* normal = cmd->add_option("--normal", o->normal, "oblique plane: normal NX,NY,NZ in LPS")
                     ->delimiter(',')
                     ->expected(3);
  normal->excludes(plane)->excludes(index)->excludes(mm);
  cmd->add_option("--point", o->point,
                  "a point X,Y,Z (LPS mm) the plane passes through "
                  "(default: the volume's centre)")
      ->delimiter(',')
      ->expected(3)
      ->excludes(index)
      ->excludes(mm);
  cmd->add_option("--slab", o->slabMm, "slab thickness in mm (0: a thin slice)")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--slab-mode", o->slabMode, "mip, minip or mean")
      ->check(CLI::IsMember({"mip", "minip", "mean"}));
  cmd->add_option("--interp", o->interp, "linear (trilinear, default) or nearest")
      ->check(CLI::IsMember({"linear", "nearest"}));
  cmd->add_option("--wl", o->wl, "window width,level (default: the file's, else the modality's)")
      ->delimiter(',')
      ->expected(2);
  return [o, index, mm] {
    o->hasIndex = index->count() > 0;
    o->hasMm = mm->count() > 0;
    const auto start = std::chrono::steady_clock::now();
    Volume v = o->input.load();
    if (v.voxelCount() == 0) throw inputError("the volume is empty: nothing to slice");
    const Chosen c = choosePlane(v, *o);
    if (planeInBox(v, c.centre, rotateFrame(c.rotation, baseFrame(v.direction, c.axes)).normal)
            .empty())
      throw inputError("the plane misses the volume: give a --point or --mm inside it");
    WindowLevel wl = initialWindow(v).wl;
    if (!o->wl.empty()) {
      if (!(o->wl[0] > 0.0)) throw inputError("--wl: the window width must be above 0");
      wl = {o->wl[0], o->wl[1]};
    }
    const Slab slab{o->slabMm, parseSlabMode(o->slabMode)};
    const PlaneGrid g = viewPlane(v, c.axes, c.centre, c.rotation);
    const auto sliced = std::chrono::steady_clock::now();
    Image img = renderPlane(v, g, wl, parseInterp(o->interp), slab);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sliced)
            .count();
    writeImage(o->output, img);
    std::cerr << "sliced " << g.size.x << "x" << g.size.y << " px of " << g.spacingMm.x << " mm, "
              << toString(c.axes.orientation) << (c.rotation == glm::dmat3(1.0) ? "" : " turned")
              << ", slab " << slab.thicknessMm << " mm " << toString(slab.mode) << " ("
              << slabSamples(v, slab) << " samples per pixel) in " << ms << " ms ("
              << std::chrono::duration<double, std::milli>(sliced - start).count()
              << " ms loading) -> " << o->output << "\n";
    return 0;
  };
}

}  // namespace voxray::cli
