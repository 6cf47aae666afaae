#include "measurement_json.h"

#include <string>

#include "voxray/io/error.h"

namespace voxray {

namespace {

constexpr double kMaxCoordinate = 1e6;  // voxels

constexpr MeasureKind kKinds[] = {MeasureKind::Distance, MeasureKind::Angle, MeasureKind::Ellipse,
                                  MeasureKind::Rect};

Measurement parseItem(const nlohmann::json& item, size_t n) {
  const std::string where = "measurement " + std::to_string(n + 1) + " in the session: ";
  if (!item.is_object()) throw inputError(where + "is not an object");
  Measurement m;
  // Each field's type is checked first: nlohmann's own type errors are not Voxray errors.
  const auto kindIt = item.find("kind");
  const std::string kind =
      kindIt != item.end() && kindIt->is_string() ? kindIt->get<std::string>() : std::string();
  bool known = false;
  for (MeasureKind k : kKinds)
    if (kind == toString(k)) {
      m.kind = k;
      known = true;
    }
  if (!known)
    throw inputError(where + "unknown kind '" + kind + "' (distance, angle, ellipse or rect)");
  const auto axisIt = item.find("normal_axis");
  if (axisIt != item.end() && !axisIt->is_number_integer())
    throw inputError(where + "normal_axis must be -1, 0, 1 or 2");
  m.normalAxis = axisIt != item.end() ? axisIt->get<int>() : 2;
  if (m.normalAxis < -1 || m.normalAxis > 2)
    throw inputError(where + "normal_axis must be -1, 0, 1 or 2");
  const auto pointsIt = item.find("points");
  if (pointsIt == item.end() || !pointsIt->is_array() ||
      int(pointsIt->size()) != pointCount(m.kind))
    throw inputError(where + "a " + kind + " needs " + std::to_string(pointCount(m.kind)) +
                     " points");
  for (const auto& p : *pointsIt) {
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
        !p[2].is_number())
      throw inputError(where + "a point must be [i, j, k] in voxels");
    glm::dvec3 v(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    // Far beyond any volume (and beyond exact integers in a double): a broken file.
    if (!glm::all(glm::lessThan(glm::abs(v), glm::dvec3(kMaxCoordinate))))
      throw inputError(where + "a point coordinate is not a number within +-1e6 voxels");
    m.points.push_back(v);
  }
  return m;
}

}  // namespace

nlohmann::json measurementsToJson(const MeasurementModel& model) {
  nlohmann::json items = nlohmann::json::array();
  for (const auto& m : model.items()) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : m.points) points.push_back({p.x, p.y, p.z});
    items.push_back(
        {{"kind", toString(m.kind)}, {"normal_axis", m.normalAxis}, {"points", points}});
  }
  return {{"show_in_exports", model.showInExports()}, {"items", items}};
}

void measurementsFromJson(const nlohmann::json& j, MeasurementModel& model) {
  if (!j.is_object()) throw inputError("measurements in the session: expected an object");
  std::vector<Measurement> parsed;
  const auto itemsIt = j.find("items");
  const nlohmann::json none = nlohmann::json::array();
  const auto& items = itemsIt != j.end() ? *itemsIt : none;
  if (!items.is_array()) throw inputError("measurements in the session: 'items' is not a list");
  for (size_t n = 0; n < items.size(); ++n) parsed.push_back(parseItem(items[n], n));
  const auto showIt = j.find("show_in_exports");
  const bool show = showIt != j.end() && showIt->is_boolean() && showIt->get<bool>();
  model.clear();
  for (auto& m : parsed) model.add(m.kind, std::move(m.points), m.normalAxis);
  model.select(0);
  model.setShowInExports(show);
}

}  // namespace voxray
