// voxray-cli: the headless front end. Errors end in one line on stderr and exit code 1;
// usage errors exit 2, internal errors (a bug: any exception that is not voxray::Error) 3.
// No exception reaches the runtime: a user never sees an abort.
#include <iostream>

#include "commands.h"
#include "terminal_text.h"
#include "voxray/io/error.h"

int main(int argc, char** argv) {
  CLI::App app{"Voxray: CT/MR volume raycasting on OpenCL (headless)"};
  app.require_subcommand(1);
  std::vector<voxray::cli::Run> runs = {
      voxray::cli::addDevicesCommand(app), voxray::cli::addInfoCommand(app),
      voxray::cli::addRenderCommand(app),  voxray::cli::addPresetsCommand(app),
      voxray::cli::addBenchCommand(app),   voxray::cli::addAccuracyCommand(app),
      voxray::cli::addMeasureCommand(app), voxray::cli::addSliceCommand(app),
      voxray::cli::addPacsCommand(app),    voxray::cli::addMovieCommand(app),
      voxray::cli::addTfCommand(app),      voxray::cli::addMakePhantomCommand(app),
      voxray::cli::addDbCommand(app),      voxray::cli::addSegmentCommand(app)};
  // Issue 37, results out (after the list: the runs follow the subcommands' order).
  runs.push_back(voxray::cli::addExportSrCommand(app));
  runs.push_back(voxray::cli::addKeyImagesCommand(app));
  runs.push_back(voxray::cli::addAnonymiseCommand(app));
  // Issue 38: OME-Zarr out.
  runs.push_back(voxray::cli::addConvertCommand(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  auto chosen = app.get_subcommands();
  const auto& all = app.get_subcommands({});
  for (size_t i = 0; i < all.size(); ++i) {
    if (all[i] != chosen.front()) continue;
    try {
      return runs[i]();
    } catch (const voxray::Error& e) {
      // Messages quote servers and files (a content type, a DICOM string): escaped, they
      // stay one line and cannot drive the terminal.
      std::cerr << "voxray-cli: " << voxray::cli::terminalText(e.what()) << "\n";
      return 1;
    } catch (const std::bad_alloc&) {
      std::cerr << "voxray-cli: out of memory: the volume or image is too large for this "
                   "machine\n";
      return 1;
    } catch (const std::exception& e) {
      // A bug, not the user's input: say so rather than abort.
      std::cerr << "voxray-cli: internal error (" << voxray::cli::terminalText(e.what())
                << "); please report it with the command that caused it\n";
      return 3;
    } catch (...) {
      std::cerr << "voxray-cli: internal error (an unknown exception); please report it with "
                   "the command that caused it\n";
      return 3;
    }
  }
  return 2;
}
