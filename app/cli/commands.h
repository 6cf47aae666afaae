#pragma once
// The subcommands of voxray-cli. Each registers its flags on the parser and returns the
// function that runs it; main() catches voxray::Error at the top.
#include <functional>

#include <CLI/CLI.hpp>

namespace voxray::cli {

using Run = std::function<int()>;

Run addDevicesCommand(CLI::App& app);
Run addInfoCommand(CLI::App& app);
Run addRenderCommand(CLI::App& app);
Run addPresetsCommand(CLI::App& app);
Run addBenchCommand(CLI::App& app);
Run addAccuracyCommand(CLI::App& app);
Run addMeasureCommand(CLI::App& app);
Run addSliceCommand(CLI::App& app);
Run addPacsCommand(CLI::App& app);
Run addMovieCommand(CLI::App& app);
Run addTfCommand(CLI::App& app);
Run addMakePhantomCommand(CLI::App& app);
Run addDbCommand(CLI::App& app);
Run addSegmentCommand(CLI::App& app);
Run addExportSrCommand(CLI::App& app);
Run addKeyImagesCommand(CLI::App& app);
Run addAnonymiseCommand(CLI::App& app);
Run addConvertCommand(CLI::App& app);

}  // namespace voxray::cli
