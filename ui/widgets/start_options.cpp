#include "start_options.h"

#include <QCommandLineParser>

#include "voxray/engine/render_params.h"
#include "voxray/io/error.h"
#include "voxray/io/orientation.h"

namespace voxray::ui {

namespace {

std::vector<double> numbers(const QString& flag, const QString& text, int minCount, int maxCount) {
  std::vector<double> out;
  for (const QString& part : text.split(',')) {
    bool ok = false;
    out.push_back(part.trimmed().toDouble(&ok));
    if (!ok)
      throw inputError("--" + flag.toStdString() + ": '" + part.toStdString() +
                       "' is not a number");
  }
  if (int(out.size()) < minCount || int(out.size()) > maxCount)
    throw inputError("--" + flag.toStdString() + ": expected " + std::to_string(maxCount) +
                     " comma-separated numbers, got '" + text.toStdString() + "'");
  return out;
}

}  // namespace

StartOptions parseStartOptions(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Voxray workstation: CT/MR volumes, slices and 3D raycast");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("input", "DICOM file or folder, raw slice folder or raw file");
  const QList<QCommandLineOption> raw = {
      {"raw-dims", "raw: X,Y[,Z] voxels (Z: number of slice files)", "X,Y,Z"},
      {"raw-type", "raw: u8, i16, u16 or f32", "type", "i16"},
      {"raw-endian", "raw: big or little", "order", "little"},
      {"raw-spacing", "raw: SX,SY,SZ in mm", "SX,SY,SZ"},
      {"raw-offset", "raw: header bytes to skip in each file", "bytes", "0"},
      {"raw-rescale", "raw: SLOPE,INTERCEPT to HU", "S,I"},
      {"raw-range", "raw: FIRST-LAST slice numbers", "range"},
      {"raw-axes", "raw: patient direction of the x, y, z axes, e.g. LPI (default LPS)", "code"},
      {"series", "DICOM: series number or UID", "series"},
      {"device", "OpenCL device: auto, cpu, gpu or a number ($VOXRAY_DEVICE)", "device"},
      {"screenshot", "after the first full-quality frame, save the window to FILE", "file"},
      {"quit-after-first-frame", "quit after the first full-quality frame (tests)"},
      {"reset-settings", "ignore the saved window state and settings"},
  };
  parser.addOptions(raw);
  for (const auto& spec : renderParamSpecs())
    parser.addOption({QString::fromStdString(spec.key), QString::fromStdString(spec.help),
                      QString::fromStdString(spec.valueHint)});
  parser.process(arguments);

  StartOptions o;
  if (!parser.positionalArguments().isEmpty())
    o.input = parser.positionalArguments().first().toStdString();
  o.load.series = parser.value("series").toStdString();
  if (parser.isSet("raw-dims")) {
    RawLayout l;
    auto d = numbers("raw-dims", parser.value("raw-dims"), 2, 3);
    l.dims = {int(d[0]), int(d[1]), d.size() > 2 ? int(d[2]) : 0};
    l.type = parseSampleType(parser.value("raw-type").toStdString());
    l.order = parseByteOrder(parser.value("raw-endian").toStdString());
    if (parser.isSet("raw-spacing")) {
      auto s = numbers("raw-spacing", parser.value("raw-spacing"), 3, 3);
      l.spacingMm = {s[0], s[1], s[2]};
    }
    l.headerBytes = size_t(parser.value("raw-offset").toULongLong());
    if (parser.isSet("raw-rescale")) {
      auto r = numbers("raw-rescale", parser.value("raw-rescale"), 2, 2);
      l.slope = r[0];
      l.intercept = r[1];
    }
    if (parser.isSet("raw-range")) {
      QStringList parts = parser.value("raw-range").split('-');
      if (parts.size() != 2) throw inputError("--raw-range: expected FIRST-LAST, e.g. 1-113");
      l.range = std::make_pair(parts[0].toInt(), parts[1].toInt());
    }
    if (parser.isSet("raw-axes"))
      l.direction = directionFromAxesCode(parser.value("raw-axes").toStdString());
    o.load.raw = l;
  }
  for (const auto& spec : renderParamSpecs()) {
    QString key = QString::fromStdString(spec.key);
    if (parser.isSet(key)) o.renderValues[spec.key] = parser.value(key).toStdString();
  }
  o.device = parser.value("device").toStdString();
  o.screenshot = parser.value("screenshot").toStdString();
  o.quitAfterFirstFrame = parser.isSet("quit-after-first-frame");
  o.resetSettings = parser.isSet("reset-settings");
  return o;
}

}  // namespace voxray::ui
