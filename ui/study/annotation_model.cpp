#include "annotation_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slice_geometry.h"
#include "voxray/engine/measure.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// Planes within a degree of each other are one orientation: a view's normal and the one the
// annotation saved agree to rounding, and a session's JSON keeps ~17 digits.
const double kParallelCos = std::cos(glm::radians(1.0));

bool nearPlane(const glm::dvec3& p, const glm::dvec3& normal, const glm::dvec3& pointMm,
               double spacingMm) {
  return std::abs(glm::dot(p - pointMm, normal)) < 0.5 * spacingMm;
}

}  // namespace

bool annotationOnPlane(const Annotation& a, const glm::dvec3& normal, const glm::dvec3& pointMm,
                       double spacingMm) {
  if (std::abs(glm::dot(a.normal, normal)) < kParallelCos) return false;
  if (!nearPlane(a.anchorMm, normal, pointMm, spacingMm)) return false;
  return !a.tailMm || nearPlane(*a.tailMm, normal, pointMm, spacingMm);
}

glm::dvec3 sliceNormal(const Volume& v, const SliceAxes& axes) {
  // The in-plane axes' cross product: on a tilted (sheared) grid the slice axis is not the
  // plane's normal.
  return glm::normalize(glm::cross(v.direction[axes.uAxis], v.direction[axes.vAxis]));
}

bool annotationOnSlice(const Annotation& a, const Volume& v, const SliceAxes& axes, int slice) {
  const glm::dvec3 n = sliceNormal(v, axes);
  glm::dvec3 voxel(0.0);
  voxel[axes.nAxis] = slice;
  // The distance between slices measured along the normal.
  const double spacing = v.spacingMm[axes.nAxis] * std::abs(glm::dot(v.direction[axes.nAxis], n));
  return annotationOnPlane(a, n, voxelToPatient(v, voxel), spacing);
}

const Annotation* AnnotationModel::find(int id) const {
  auto it = std::find_if(items_.begin(), items_.end(), [id](const auto& a) { return a.id == id; });
  return it == items_.end() ? nullptr : &*it;
}

void AnnotationModel::commit(const std::string& what, std::vector<Annotation> after) {
  history_.resize(done_);  // a new step drops what was undone
  history_.push_back({what, items_, after});
  done_ = history_.size();
  items_ = std::move(after);
  changed.notify();
}

int AnnotationModel::addText(const std::string& text, const glm::dvec3& anchorMm,
                             const glm::dvec3& normal) {
  Annotation a;
  a.id = nextId_++;
  a.text = text;
  a.anchorMm = anchorMm;
  a.normal = glm::normalize(normal);
  auto after = items_;
  after.push_back(a);
  selected_ = a.id;
  commit("Add text", std::move(after));
  return a.id;
}

int AnnotationModel::addArrow(const glm::dvec3& headMm, const glm::dvec3& tailMm,
                              const glm::dvec3& normal, const std::string& text) {
  Annotation a;
  a.id = nextId_++;
  a.text = text;
  a.anchorMm = headMm;
  a.tailMm = tailMm;
  a.normal = glm::normalize(normal);
  auto after = items_;
  after.push_back(a);
  selected_ = a.id;
  commit("Add arrow", std::move(after));
  return a.id;
}

void AnnotationModel::setText(int id, const std::string& text) {
  const Annotation* a = find(id);
  if (!a || a->text == text) return;
  auto after = items_;
  for (auto& x : after)
    if (x.id == id) x.text = text;
  commit("Edit annotation", std::move(after));
}

void AnnotationModel::remove(int id) {
  if (!find(id)) return;
  auto after = items_;
  std::erase_if(after, [id](const auto& a) { return a.id == id; });
  if (selected_ == id) selected_ = 0;
  commit("Delete annotation", std::move(after));
}

void AnnotationModel::clear() { reset({}); }

void AnnotationModel::reset(std::vector<Annotation> items) {
  for (Annotation& a : items) a.id = nextId_++;
  items_ = std::move(items);
  history_.clear();
  done_ = 0;
  selected_ = 0;
  changed.notify();
}

void AnnotationModel::select(int id) {
  selected_ = find(id) ? id : 0;
  changed.notify();
}

std::string AnnotationModel::undoText() const {
  return canUndo() ? "Undo " + history_[done_ - 1].what : std::string();
}

std::string AnnotationModel::redoText() const {
  return canRedo() ? "Redo " + history_[done_].what : std::string();
}

void AnnotationModel::undo() {
  if (!canUndo()) return;
  items_ = history_[--done_].before;
  if (!find(selected_)) selected_ = 0;
  changed.notify();
}

void AnnotationModel::redo() {
  if (!canRedo()) return;
  items_ = history_[done_++].after;
  if (!find(selected_)) selected_ = 0;
  changed.notify();
}

namespace {

std::string lps(const glm::dvec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.1f, %.1f, %.1f) mm", p.x, p.y, p.z);
  return buf;
}

}  // namespace

std::vector<std::string> annotationReportTexts(const AnnotationModel& m) {
  std::vector<std::string> out;
  for (const Annotation& a : m.items()) {
    std::string line = a.tailMm ? "arrow from " + lps(*a.tailMm) + " to " + lps(a.anchorMm)
                                : "text at " + lps(a.anchorMm);
    if (!a.text.empty()) line += ": " + a.text;
    out.push_back(line);
  }
  return out;
}

namespace {

constexpr double kMaxMm = 1e7;  // far beyond any scanner: a broken file

nlohmann::json vec(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

glm::dvec3 readVec(const nlohmann::json& item, const char* key, const std::string& where) {
  const auto it = item.find(key);
  if (it == item.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() ||
      !(*it)[1].is_number() || !(*it)[2].is_number())
    throw inputError(where + "'" + key + "' must be [x, y, z] in mm");
  const glm::dvec3 v((*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>());
  if (!glm::all(glm::lessThan(glm::abs(v), glm::dvec3(kMaxMm))))
    throw inputError(where + "'" + key + "' is not a number within +-1e7 mm");
  return v;
}

}  // namespace

nlohmann::json annotationsToJson(const AnnotationModel& m) {
  nlohmann::json items = nlohmann::json::array();
  for (const Annotation& a : m.items()) {
    nlohmann::json j = {{"text", a.text}, {"anchor_mm", vec(a.anchorMm)}};
    if (a.tailMm) j["tail_mm"] = vec(*a.tailMm);
    j["normal"] = vec(a.normal);
    items.push_back(j);
  }
  return items;
}

void annotationsFromJson(const nlohmann::json& j, AnnotationModel& m) {
  if (!j.is_array()) throw inputError("annotations in the session: expected a list [ ... ]");
  std::vector<Annotation> parsed;
  for (size_t n = 0; n < j.size(); ++n) {
    const std::string where = "annotation " + std::to_string(n + 1) + " in the session: ";
    const auto& item = j[n];
    if (!item.is_object()) throw inputError(where + "is not an object");
    Annotation a;
    const auto textIt = item.find("text");
    if (textIt != item.end() && !textIt->is_string())
      throw inputError(where + "'text' must be a string");
    if (textIt != item.end()) a.text = textIt->get<std::string>();
    a.anchorMm = readVec(item, "anchor_mm", where);
    if (item.contains("tail_mm")) a.tailMm = readVec(item, "tail_mm", where);
    a.normal = readVec(item, "normal", where);
    if (glm::length(a.normal) < 1e-6) throw inputError(where + "'normal' has no direction");
    if (!a.tailMm && a.text.empty()) throw inputError(where + "a text annotation has no text");
    parsed.push_back(a);
  }
  // A session's annotations are where the reading starts, not steps to take back.
  m.reset(std::move(parsed));
}

}  // namespace voxray
