#include "start_options.h"

#include <QCommandLineParser>

#include "voxray/engine/input_flags.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/error.h"
#include "voxray/io/sample_volume.h"

namespace voxray::ui {

namespace {

// Declared parameters (render_params.h, input_flags.h) as options, and what the user gave.
template <class Spec>
void addSpecOptions(QCommandLineParser& parser, const std::vector<Spec>& specs) {
  for (const auto& spec : specs)
    parser.addOption({QString::fromStdString(spec.key), QString::fromStdString(spec.help),
                      QString::fromStdString(spec.valueHint)});
}

template <class Spec>
std::map<std::string, std::string> givenValues(const QCommandLineParser& parser,
                                               const std::vector<Spec>& specs) {
  std::map<std::string, std::string> out;
  for (const auto& spec : specs) {
    QString key = QString::fromStdString(spec.key);
    if (parser.isSet(key)) out[spec.key] = parser.value(key).toStdString();
  }
  return out;
}

}  // namespace

StartOptions parseStartOptions(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Voxray workstation: CT/MR volumes, slices and 3D raycast");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("input", "DICOM file or folder, raw slice folder or raw file");
  parser.addOptions({
      {"device", "OpenCL device: auto, cpu, gpu or a number ($VOXRAY_DEVICE)", "device"},
      {"screenshot", "after the first full-quality frame, save the window to FILE", "file"},
      {"quit-after-first-frame", "quit after the first full-quality frame (tests)"},
      {"reset-settings", "ignore the saved window state and settings"},
      {"startup-times",
       "print to stderr when the slice views and the first 3D images were shown (ms since start)"},
      {"phantom", "open the synthetic head phantom instead of the sample CT (no INPUT)"},
      {"overlay", "fuse INPUT (a volume file or DICOM folder) over the study", "input"},
      {"compare", "open INPUT beside the study as a prior (compare mode)", "input"},
  });
  addSpecOptions(parser, inputFlagSpecs());
  addSpecOptions(parser, renderParamSpecs());
  parser.process(arguments);

  StartOptions o;
  if (!parser.positionalArguments().isEmpty()) {
    if (parser.isSet("phantom"))
      throw inputError("--phantom opens the synthetic phantom: give it without an INPUT");
    o.input = parser.positionalArguments().first().toStdString();
    o.inputGiven = true;
  } else if (parser.isSet("phantom")) {
    o.inputGiven = true;
  } else {
    o.input = kSampleCtInput;
  }
  o.load = loadOptionsFromFlags(givenValues(parser, inputFlagSpecs()));
  o.renderValues = givenValues(parser, renderParamSpecs());
  o.device = parser.value("device").toStdString();
  o.screenshot = parser.value("screenshot").toStdString();
  o.overlay = parser.value("overlay").toStdString();
  o.prior = parser.value("compare").toStdString();
  o.quitAfterFirstFrame = parser.isSet("quit-after-first-frame");
  o.resetSettings = parser.isSet("reset-settings");
  o.startupTimes = parser.isSet("startup-times");
  return o;
}

bool asksForHelpOrVersion(const QStringList& arguments) {
  static const QStringList asks = {"-h", "--help", "-?", "--help-all", "-v", "--version"};
  for (qsizetype i = 1; i < arguments.size() && arguments[i] != "--"; ++i)
    if (asks.contains(arguments[i])) return true;
  return false;
}

bool opensStudyBrowserAtStart(const StartOptions& options, bool databaseHasStudies) {
  return databaseHasStudies && !options.inputGiven && options.screenshot.empty() &&
         !options.quitAfterFirstFrame;
}

}  // namespace voxray::ui
