#pragma once
// The voxray command line: an input with voxray-cli's input flags (input_flags.h), every
// declared render parameter as --KEY VALUE (the same keys as voxray-cli render), and the
// smoke-test switches --screenshot FILE, --quit-after-first-frame and --startup-times.
#include <map>
#include <optional>
#include <string>

#include <QStringList>

#include "voxray/io/load.h"

namespace voxray::ui {

struct StartOptions {
  std::string input;  // kSampleCtInput without INPUT; empty (the head phantom) for --phantom
  LoadOptions load;   // raw layout and series (no progress or cancel yet)
  std::map<std::string, std::string> renderValues;  // --KEY VALUE of renderParamSpecs()
  std::string device;
  std::string screenshot;
  std::string overlay;  // --overlay INPUT: fused over the study once it is shown (issue 36)
  std::string prior;    // --compare INPUT: opened beside the study as a prior (compare mode)
  bool quitAfterFirstFrame = false;
  bool resetSettings = false;  // start from defaults, ignoring saved state
  bool startupTimes = false;   // print when slices and 3D images first showed (issue 41 item 9)
  bool inputGiven = false;     // an INPUT or --phantom: the user named what to open
};

// Issue 37: started without a file (no INPUT, no --phantom) and with studies in the study
// database, the workstation opens its study browser over the window (the sample CT loads
// behind it): a reader's day starts from the list of studies. Never for --screenshot or
// --quit-after-first-frame (the smoke tests' start).
bool opensStudyBrowserAtStart(const StartOptions& options, bool databaseHasStudies);

// Throws Error (Input) for a malformed value; --help and --version exit like Qt's parser.
StartOptions parseStartOptions(const QStringList& arguments);

// Whether ARGUMENTS (the program first) ask for help or the version (-h, --help, -?,
// --help-all, -v, --version, before a "--"): those print and exit, and need no display.
bool asksForHelpOrVersion(const QStringList& arguments);

}  // namespace voxray::ui
