#include "settings_store.h"

#include <QCryptographicHash>

#include "study_state.h"
#include "voxray/io/orientation.h"

namespace voxray::ui {

namespace {

// QSettings keys cannot hold arbitrary paths: key raw layouts by a hash of the path.
QString rawKey(const std::string& path) {
  return "rawLayouts/" +
         QCryptographicHash::hash(QByteArray::fromStdString(path), QCryptographicHash::Sha1)
             .toHex();
}

}  // namespace

void saveModelSettings(QSettings& s, const AppModels& m) {
  s.setValue("render/preferences", QString::fromStdString(preferencesText(m)));
  // Older versions saved the whole state, window/level included: per-study state that
  // must not come back (study_state.h).
  for (const char* old : {"render/state", "slices/window", "slices/level"}) s.remove(old);
}

void loadModelSettings(QSettings& s, AppModels& m) {
  // An older version's whole state still holds the user's preferences: applyPreferences
  // takes only those.
  const char* key = s.contains("render/preferences") ? "render/preferences" : "render/state";
  if (s.contains(key)) applyPreferences(m.render, s.value(key).toString().toStdString());
}

std::vector<std::string> loadRecent(QSettings& s) {
  std::vector<std::string> out;
  for (const QString& p : s.value("recentFiles").toStringList()) out.push_back(p.toStdString());
  return out;
}

void saveRecent(QSettings& s, const std::vector<std::string>& list) {
  QStringList l;
  for (const auto& p : list) l << QString::fromStdString(p);
  s.setValue("recentFiles", l);
}

void saveRawLayoutFor(QSettings& s, const std::string& path, const RawLayout& l) {
  s.beginGroup(rawKey(path));
  s.setValue("dims", QList<QVariant>{l.dims.x, l.dims.y, l.dims.z});
  s.setValue("type", toString(l.type));
  s.setValue("bigEndian", l.order == ByteOrder::Big);
  s.setValue("spacing", QList<QVariant>{l.spacingMm.x, l.spacingMm.y, l.spacingMm.z});
  s.setValue("header", qulonglong(l.headerBytes));
  s.setValue("slope", l.slope);
  s.setValue("intercept", l.intercept);
  s.setValue("axes", QString::fromStdString(axesCodeFromDirection(l.direction)));
  if (l.range)
    s.setValue("range", QList<QVariant>{l.range->first, l.range->second});
  else
    s.remove("range");
  s.endGroup();
}

std::optional<RawLayout> loadRawLayoutFor(QSettings& s, const std::string& path) {
  s.beginGroup(rawKey(path));
  std::optional<RawLayout> out;
  if (s.contains("dims")) {
    RawLayout l;
    auto d = s.value("dims").toList();
    auto sp = s.value("spacing").toList();
    if (d.size() == 3 && sp.size() == 3) {
      l.dims = {d[0].toInt(), d[1].toInt(), d[2].toInt()};
      l.spacingMm = {sp[0].toDouble(), sp[1].toDouble(), sp[2].toDouble()};
      l.order = s.value("bigEndian").toBool() ? ByteOrder::Big : ByteOrder::Little;
      l.headerBytes = size_t(s.value("header").toULongLong());
      l.slope = s.value("slope", 1.0).toDouble();
      l.intercept = s.value("intercept", 0.0).toDouble();
      auto r = s.value("range").toList();
      if (r.size() == 2) l.range = std::make_pair(r[0].toInt(), r[1].toInt());
      try {
        l.type = parseSampleType(s.value("type").toString().toStdString());
        // Saved before orientation existed: LPS, what those loads used.
        l.direction = directionFromAxesCode(s.value("axes", "LPS").toString().toStdString());
        out = l;
      } catch (const std::exception&) {
        // Edited by hand into nonsense: better to ask again than to load it wrongly.
      }
    }
  }
  s.endGroup();
  return out;
}

}  // namespace voxray::ui
