// The session's "reading": the reading layout and the series a hanging protocol placed in
// each view (issue 37).
#include "session_sections.h"

namespace voxray {

namespace session_detail {

Json readingJson(const ReadingLayout& l) {
  Json views = Json::object();
  for (const PlacedView& p : l.placed) {
    Json v = Json::object();
    if (!p.series.empty()) v["series"] = p.series;
    if (!p.uid.empty()) v["uid"] = p.uid;
    if (!p.description.empty()) v["description"] = p.description;
    if (!p.note.empty()) v["note"] = p.note;
    views[gridViewName(p.view)] = v;
  }
  Json j = {{"layout", layoutName(l.layout)}};
  if (!views.empty()) j["views"] = views;
  return j;
}

void readReading(Reader& r, const Json& root, Session& s) {
  if (!root.contains("reading")) return;
  const Json& reading = r.object(root, "reading", "reading");
  r.warnUnknown(reading, "reading.", {"layout", "views"});
  ReadingLayout l;
  const std::string name = r.text(r.require(reading, "reading.layout", "layout"), "reading.layout");
  const auto layout = parseLayout(name);
  if (!layout) r.fail("reading.layout", "must be one of 1x1, 1x2, 2x2, 1+3, mpr+3d, 3d");
  l.layout = *layout;
  if (reading.contains("views")) {
    const Json& views = r.object(reading, "reading.views", "views");
    for (const auto& item : views.items()) {
      const std::string field = "reading.views." + item.key();
      const auto view = parseGridView(item.key());
      if (!view) {
        r.unknown(field);
        continue;
      }
      const Json& v = r.object(views, field, item.key());
      r.warnUnknown(v, field + ".", {"series", "uid", "description", "note"});
      PlacedView p;
      p.view = *view;
      if (v.contains("series")) p.series = r.text(v.at("series"), field + ".series");
      if (v.contains("uid")) p.uid = r.text(v.at("uid"), field + ".uid");
      if (v.contains("description"))
        p.description = r.text(v.at("description"), field + ".description");
      if (v.contains("note")) p.note = r.text(v.at("note"), field + ".note");
      if (p.series.empty() && p.note.empty()) p.note = "left empty when the session was saved";
      l.placed.push_back(p);
    }
  }
  s.reading = l;
}

}  // namespace session_detail

}  // namespace voxray
