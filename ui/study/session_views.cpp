// The session's "render" (every render parameter by its spec), the slice views' turned planes
// and slabs ("slices.views", "slices.centre") and the 3D view's "overlays".
#include "session_sections.h"

#include <cmath>
#include <utility>

namespace voxray {

namespace session_detail {

namespace {

constexpr std::array<const char*, 3> kViewNames = {"axial", "coronal", "sagittal"};

}  // namespace

void readRender(Reader& r, const Json& root, RenderParams& p) {
  const Json& render = r.object(root, "render", "render");
  std::vector<std::string> known;
  // Declaration order: "light" (which fixes the light) before "light-follows-camera".
  for (const auto& spec : renderParamSpecs()) {
    known.push_back(spec.key);
    const std::string field = "render." + spec.key;
    auto it = render.find(spec.key);
    if (it == render.end()) {
      r.warnings.push_back("field '" + field + "' missing: left at its default (" + spec.format(p) +
                           ")");
      continue;
    }
    try {
      spec.parse(p, r.valueText(*it, field));
    } catch (const Error& e) {
      r.fail(field, std::string("is wrong: ") + e.what());
    }
  }
  r.warnUnknown(render, "render.", known);
}

// The views that are turned or thick, by name; absent views are acquisition planes, thin.
Json viewsJson(const std::array<SessionView, 3>& views) {
  Json j = Json::object();
  for (size_t o = 0; o < views.size(); ++o) {
    const SessionView& v = views[o];
    if (v.rotation == glm::dmat3(1.0) && v.slab.thicknessMm == 0.0) continue;
    Json rows = Json::array();  // row by row, as the matrix is written on paper
    for (int r = 0; r < 3; ++r)
      rows.push_back({v.rotation[0][r], v.rotation[1][r], v.rotation[2][r]});
    j[kViewNames[o]] = {
        {"rotation", rows}, {"slab-mm", v.slab.thicknessMm}, {"slab-mode", toString(v.slab.mode)}};
  }
  return j;
}

void readViews(Reader& r, const Json& slices, Session& s) {
  if (!slices.contains("views")) return;
  const Json& views = r.object(slices, "slices.views", "views");
  r.warnUnknown(views, "slices.views.", {kViewNames.begin(), kViewNames.end()});
  for (size_t o = 0; o < kViewNames.size(); ++o) {
    if (!views.contains(kViewNames[o])) continue;
    const std::string field = std::string("slices.views.") + kViewNames[o];
    const Json& view = r.object(views, field, kViewNames[o]);
    r.warnUnknown(view, field + ".", {"rotation", "slab-mm", "slab-mode"});
    SessionView& v = s.views[o];
    if (view.contains("rotation")) {
      const Json& rows = view.at("rotation");
      const std::string want = "must be 3 rows of 3 numbers: a rotation";
      if (!rows.is_array() || rows.size() != 3) r.fail(field + ".rotation", want);
      for (int row = 0; row < 3; ++row) {
        auto n = r.numbers(rows.at(size_t(row)), field + ".rotation", 3);
        for (int col = 0; col < 3; ++col) v.rotation[col][row] = n[size_t(col)];
      }
      // A hand-edited matrix that is no rotation would shear the planes: refuse it.
      const glm::dmat3 error = glm::transpose(v.rotation) * v.rotation - glm::dmat3(1.0);
      double worst = 0.0;
      for (int c = 0; c < 3; ++c)
        for (int rr = 0; rr < 3; ++rr) worst = std::max(worst, std::abs(error[c][rr]));
      if (!(worst < 1e-6) || glm::determinant(v.rotation) < 0.0)
        r.fail(field + ".rotation", "is not a rotation (orthonormal, determinant 1)");
    }
    if (view.contains("slab-mm")) {
      v.slab.thicknessMm = r.number(view.at("slab-mm"), field + ".slab-mm");
      if (!(v.slab.thicknessMm >= 0.0) || !std::isfinite(v.slab.thicknessMm))
        r.fail(field + ".slab-mm", "must be 0 (a thin slice) or more millimetres");
    }
    if (view.contains("slab-mode")) {
      try {
        v.slab.mode = parseSlabMode(r.text(view.at("slab-mode"), field + ".slab-mode"));
      } catch (const Error& e) {
        r.fail(field + ".slab-mode", std::string("is wrong: ") + e.what());
      }
    }
  }
  if (slices.contains("centre")) {
    auto c = r.numbers(slices.at("centre"), "slices.centre", 3);
    s.centre = glm::dvec3(c[0], c[1], c[2]);
  }
}

// Sessions before the overlays were saved lack the object, or a key of it: the defaults.
void readOverlays(Reader& r, const Json& root, ViewOverlays& o) {
  if (!root.contains("overlays")) return;
  const Json& overlays = r.object(root, "overlays", "overlays");
  r.warnUnknown(overlays, "overlays.", {"clip-handles", "light-handle", "planes"});
  const std::pair<const char*, bool ViewOverlays::*> fields[] = {
      {"clip-handles", &ViewOverlays::clipHandles},
      {"light-handle", &ViewOverlays::lightHandle},
      {"planes", &ViewOverlays::planes}};
  for (const auto& [key, field] : fields) {
    if (!overlays.contains(key)) continue;
    const Json& v = overlays.at(key);
    if (!v.is_boolean()) r.fail(std::string("overlays.") + key, "must be true or false");
    o.*field = v.get<bool>();
  }
}

}  // namespace session_detail

}  // namespace voxray
