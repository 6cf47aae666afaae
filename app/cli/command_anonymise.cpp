// voxray-cli anonymise: a series or study de-identified (PS3.15 Basic Profile) into a folder.
#include <iostream>
#include <optional>

#include "commands.h"
#include "voxray/io/anonymise.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

struct AnonymiseCli {
  std::string input, output;
  bool keepDates = false;
  std::optional<int> shiftDays;
  AnonymiseOptions options;
};

int runAnonymise(AnonymiseCli& o) {
  if (o.keepDates && o.shiftDays)
    throw inputError("anonymise: give --keep-dates or --shift-dates, not both");
  o.options.dates = o.keepDates   ? DateHandling::Keep
                    : o.shiftDays ? DateHandling::Shift
                                  : DateHandling::Remove;
  o.options.shiftDays = o.shiftDays.value_or(0);
  const AnonymiseResult r = anonymise(o.input, o.output, o.options);
  std::cout << o.output << ": " << r.written << " file" << (r.written == 1 ? "" : "s")
            << " de-identified (PS3.15 Basic Profile, dates "
            << (o.keepDates   ? "kept"
                : o.shiftDays ? "shifted"
                              : "removed")
            << ")";
  if (r.skipped)
    std::cout << ", " << r.skipped << " other file" << (r.skipped == 1 ? "" : "s") << " skipped";
  std::cout << "\n";
  if (r.burnedIn)
    std::cout << "note: " << r.burnedIn << " image" << (r.burnedIn == 1 ? " has" : "s have")
              << " text burned into the pixels (Burned In Annotation YES) and "
              << (r.burnedIn == 1 ? "was" : "were") << " left out\n";
  return 0;
}

}  // namespace

Run addAnonymiseCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "anonymise",
      "Copy a DICOM series or study into a folder, de-identified (PS3.15 Basic Profile)");
  auto o = std::make_shared<AnonymiseCli>();
  cmd->add_option("INPUT", o->input, "a DICOM folder (a series or a study) or file")->required();
  cmd->add_option("-o,--output", o->output, "the folder to write (never inside INPUT)")->required();
  cmd->add_option("--series", o->options.seriesUid, "only this Series Instance UID");
  cmd->add_flag("--keep-dates", o->keepDates, "keep dates and times (the Full Dates option)");
  cmd->add_option("--shift-dates", o->shiftDays,
                  "shift every date by DAYS (the Modified Dates option; default: dates removed)");
  cmd->add_flag("--force", o->options.force, "write into an existing, non-empty folder");
  return [o] { return runAnonymise(*o); };
}

}  // namespace voxray::cli
