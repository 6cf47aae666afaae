// The session's "comparison" (compare, issue 36): the prior beside the study, its series and
// own time point, the rigid map onto the study, the 3D look's link and the prior's camera.
#include "session_sections.h"

#include "comparison_model.h"

namespace voxray {

namespace session_detail {

namespace {

// The prior's 3D camera (compare): every field required, in the ranges the camera takes.
CameraParams readPriorCamera(Reader& r, const Json& comparison) {
  const std::string f = "comparison.prior-camera";
  const Json& j = r.object(comparison, f, "prior-camera");
  r.warnUnknown(
      j, f + ".",
      {"azimuth-deg", "elevation-deg", "zoom", "distance-mm", "pan-mm", "projection", "fov-deg"});
  CameraParams c;
  auto number = [&](const char* key) {
    return r.number(r.require(j, f + "." + key, key), f + "." + key);
  };
  c.azimuthDeg = number("azimuth-deg");
  c.elevationDeg = number("elevation-deg");
  c.zoom = number("zoom");
  c.distanceMm = number("distance-mm");
  c.fovDeg = number("fov-deg");
  if (!(c.zoom > 0.0)) r.fail(f + ".zoom", "must be above 0");
  if (!(c.distanceMm >= 0.0)) r.fail(f + ".distance-mm", "must be 0 (frame the volume) or more");
  if (!(c.fovDeg > 0.0 && c.fovDeg < 180.0)) r.fail(f + ".fov-deg", "must be 0 ... 180 degrees");
  const Json& pan = r.require(j, f + ".pan-mm", "pan-mm");
  if (!pan.is_array() || pan.size() != 2 || !pan[0].is_number() || !pan[1].is_number())
    r.fail(f + ".pan-mm", "must be two numbers (mm)");
  c.panMm = {pan[0].get<double>(), pan[1].get<double>()};
  const std::string p = r.text(r.require(j, f + ".projection", "projection"), f + ".projection");
  if (p != "perspective" && p != "orthographic")
    r.fail(f + ".projection", "must be perspective or orthographic");
  c.projection = p == "orthographic" ? Projection::Orthographic : Projection::Perspective;
  return c;
}

}  // namespace

Json comparisonJson(const Session& s) {
  Json c = {{"prior", s.comparison->priorPath}, {"prior-time-point", s.comparison->priorTimePoint}};
  if (!s.comparison->priorSeries.empty()) c["series"] = s.comparison->priorSeries;
  if (!s.comparison->linkLook) c["link-look"] = false;
  if (const auto& cam = s.comparison->priorCamera)
    c["prior-camera"] = {
        {"azimuth-deg", cam->azimuthDeg},
        {"elevation-deg", cam->elevationDeg},
        {"zoom", cam->zoom},
        {"distance-mm", cam->distanceMm},
        {"pan-mm", {cam->panMm.x, cam->panMm.y}},
        {"projection",
         cam->projection == Projection::Orthographic ? "orthographic" : "perspective"},
        {"fov-deg", cam->fovDeg}};
  if (s.comparison->movingToFixed) {
    Json rows = Json::array();  // row by row, as the matrix is written on paper
    for (int row = 0; row < 4; ++row) {
      Json r = Json::array();
      for (int col = 0; col < 4; ++col) r.push_back((*s.comparison->movingToFixed)[col][row]);
      rows.push_back(r);
    }
    c["moving-to-fixed"] = rows;
  }
  return c;
}

void readComparison(Reader& r, const Json& root, Session& s) {
  if (!root.contains("comparison")) return;
  const Json& c = r.object(root, "comparison", "comparison");
  r.warnUnknown(
      c, "comparison.",
      {"prior", "series", "moving-to-fixed", "link-look", "prior-camera", "prior-time-point"});
  Session::Comparison out;
  out.priorPath = r.text(r.require(c, "comparison.prior", "prior"), "comparison.prior");
  out.priorTimePoint = readTimePoint(r, c, "prior-time-point", "comparison.prior-time-point");
  if (c.contains("series")) out.priorSeries = r.text(c.at("series"), "comparison.series");
  if (c.contains("link-look")) {
    if (!c.at("link-look").is_boolean()) r.fail("comparison.link-look", "must be true or false");
    out.linkLook = c.at("link-look").get<bool>();
  }
  if (c.contains("prior-camera")) out.priorCamera = readPriorCamera(r, c);
  if (c.contains("moving-to-fixed")) {
    const std::string want =
        "must be 4 rows of 4 numbers: a rotation and a translation in mm, last row 0 0 0 1";
    const Json& rows = c.at("moving-to-fixed");
    if (!rows.is_array() || rows.size() != 4) r.fail("comparison.moving-to-fixed", want);
    glm::dmat4 m(1.0);
    for (int row = 0; row < 4; ++row) {
      const Json& values = rows.at(size_t(row));
      if (!values.is_array() || values.size() != 4) r.fail("comparison.moving-to-fixed", want);
      for (int col = 0; col < 4; ++col) {
        if (!values.at(size_t(col)).is_number()) r.fail("comparison.moving-to-fixed", want);
        m[col][row] = values.at(size_t(col)).get<double>();
      }
    }
    if (!isRigid(m)) r.fail("comparison.moving-to-fixed", want + " (this one is not rigid)");
    out.movingToFixed = m;
  }
  s.comparison = out;
}

}  // namespace session_detail

}  // namespace voxray
