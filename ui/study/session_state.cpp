#include "session_state.h"

#include "measurement_json.h"
#include "study_state.h"
#include "voxray/io/error.h"

namespace voxray {

Session sessionFromModels(const AppModels& m, const glm::ivec2& viewSize, const std::string& layout,
                          const std::optional<ReadingLayout>& reading) {
  Session s;
  s.input = m.source;
  s.render = m.render.params();
  s.render.width = viewSize.x;
  s.render.height = viewSize.y;
  s.qualityPreset = m.render.quality().preset;
  s.resolution = m.render.quality().resolution;
  s.window = m.windowLevel.value();
  s.crosshair = m.crosshair.voxel();
  if (m.crosshair.rotated()) s.centre = m.crosshair.centre();
  for (size_t o = 0; o < s.views.size(); ++o)
    s.views[o] = {m.crosshair.rotation(Orientation(o)), m.crosshair.slab(Orientation(o))};
  s.sliceInterp = m.render.sliceInterp();
  s.layout = layout;
  s.overlays = m.render.overlays();
  s.transferFunction = m.render.shapedTransferFunction();
  s.measurements = measurementsToJson(m.measurements).at("items").dump();
  s.annotations = annotationsToJson(m.annotations).dump();
  if (m.segmentation.active() && !m.segmentation.segmentation().segments.empty())
    s.segmentation = m.segmentation.segmentation();
  if (m.document.timePoints() > 1) {
    s.time = Session::Time{m.document.timePoint(), m.player.fps()};
    // voxray-cli render --session opens the input with its flags: this time point.
    s.input.flags["time"] = std::to_string(m.document.timePoint());
  }
  s.comparison = m.comparison;
  s.reading = reading;
  if (m.fusion.overlay() && !m.fusion.sourcePath().empty()) s.fusion = sessionFusion(m.fusion);
  return s;
}

Session::Fusion sessionFusion(const FusionModel& fusion) {
  Session::Fusion f;
  f.input = {fusion.sourcePath(), fusion.sourceFlags()};
  const FusionSettings& s = fusion.settings();
  f.colormap = s.colormap;
  f.lo = s.lo;
  f.hi = s.hi;
  f.opacity = s.opacity;
  f.on = s.on;
  f.timePoint = fusion.time().own();
  if (fusion.overlay()) f.unit = fusionUnit(*fusion.overlay());
  return f;
}

std::vector<std::string> applySessionFusion(FusionModel& fusion, const Session::Fusion& f) {
  std::vector<std::string> problems;
  if (!fusion.overlay()) return {"the overlay is not open: its settings were left out"};
  fusion.setSource(f.input.path, f.input.flags);
  FusionSettings s = fusion.settings();
  s.colormap = f.colormap;
  s.opacity = f.opacity;
  s.on = f.on;
  const std::string unit = fusionUnit(*fusion.overlay());
  if (f.unit.empty() || f.unit == unit) {
    s.lo = f.lo;
    s.hi = f.hi;
  } else {
    problems.push_back("the overlay's window was saved in " + f.unit +
                       " but the overlay now reads in " + unit +
                       ": its first window is shown instead");
  }
  try {
    fusion.setSettings(s);
  } catch (const Error& e) {
    problems.push_back(std::string("the overlay's saved settings were left out: ") + e.what());
  }
  if (f.timePoint >= fusion.time().count())
    problems.push_back("the overlay's time point " + std::to_string(f.timePoint) +
                       " is beyond its " + std::to_string(fusion.time().count()) +
                       " time point(s): its last is shown");
  fusion.setOwnTimePoint(f.timePoint);  // clamped
  return problems;
}

std::vector<std::string> openSession(AppModels& m, std::shared_ptr<const Volume> v,
                                     std::string name, const Session& s) {
  openStudy(m, std::move(v), std::move(name));
  return applySession(m, s);
}

std::vector<std::string> applySession(AppModels& m, const Session& s) {
  std::vector<std::string> problems;
  m.source = s.input;
  m.comparison = s.comparison;
  // The session keeps the list only: whether exports show measurements stays the user's
  // choice each time (off), as burned-in measurements must be.
  measurementsFromJson(
      {{"show_in_exports", false}, {"items", nlohmann::json::parse(s.measurements)}},
      m.measurements);
  annotationsFromJson(nlohmann::json::parse(s.annotations), m.annotations);
  Quality q = m.render.quality();
  q.preset = s.qualityPreset;
  q.resolution = s.resolution;
  m.render.setQuality(q);  // checked when read: a known preset or custom
  // Before the render state: the editor, told of the new table, then takes these lists.
  m.render.setShapedTransferFunction(s.transferFunction);
  m.render.update(kAll, [&](RenderParams& p) {
    const int width = p.width, height = p.height;  // the view decides the size
    p = s.render;
    p.width = width;
    p.height = height;
  });
  m.render.setSliceInterp(s.sliceInterp);
  m.render.setOverlays(s.overlays);
  m.windowLevel.set(s.window);
  std::array<glm::dmat3, 3> rotations;
  for (size_t o = 0; o < s.views.size(); ++o) {
    rotations[o] = s.views[o].rotation;
    m.crosshair.setSlab(Orientation(o), s.views[o].slab);
  }
  m.crosshair.setPlanes(s.centre.value_or(glm::dvec3(s.crosshair)), rotations);
  if (s.time) {
    m.player.pause();
    m.player.setFps(s.time->fps);
    m.document.setTimePoint(s.time->point);  // out of range (another series): stays
  }
  if (s.segmentation) {
    const auto& volume = m.document.volume();
    try {
      if (!volume) throw inputError("no volume is open to put it on.");
      m.segmentation.load(*s.segmentation, *volume);
    } catch (const Error& e) {
      problems.push_back(std::string("The session's segmentation was left out: ") + e.what());
    }
  }
  return problems;
}

bool isSessionPath(const std::string& path) {
  return path.size() > 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

}  // namespace voxray
