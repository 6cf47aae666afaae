// voxray-mpi: one frame over MPI ranks, sort-last (issue 38 part 5). Each rank renders the z
// slab of the volume it owns (the engine's part renderer, multi_device.h) on its own OpenCL
// device; IceT composites the parts (icet_frame.h) and rank 0 writes the image.
//
//   mpiexec -n 3 voxray-mpi INPUT [raw flags] [render flags] -o out.png [--frames N]
//
// Errors: every rank stops at the same step, rank 0 says once what failed on which rank, and
// every rank exits 1 (usage errors 2). No exception leaves a rank with the others waiting.
#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>

#include "icet_frame.h"
#include "input_options.h"
#include "rank_agreement.h"
#include "rank_slab.h"
#include "render_flags.h"
#include "slab_bounds.h"
#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"

namespace voxray::mpi {
namespace {

struct Options {
  cli::InputOptions input;
  cli::RenderFlags flags;
  std::string output, device;
  int frames = 1;
  bool wholeVolume = false;
  std::string icetColour = "float";
  std::string ess = "on";
};

std::string sliceText(const PartRange& r) {
  return "slices " + std::to_string(r.first) + "-" + std::to_string(r.end - 1);
}

// --device given (or $VOXRAY_DEVICE): that one. Otherwise this host's GPUs one per rank on
// it (its local rank), else the CPU.
std::string deviceFor(const std::string& given, MPI_Comm world) {
  if (!given.empty() || std::getenv("VOXRAY_DEVICE")) return given;
  MPI_Comm host;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host);
  int local = 0;
  MPI_Comm_rank(host, &local);
  MPI_Comm_free(&host);
  std::vector<int> gpus;
  try {
    for (const DeviceInfo& d : listDevices())
      if (d.isGpu) gpus.push_back(d.index);
  } catch (const Error&) {
    return given;  // no platform: ClContext says so with its install hint
  }
  if (gpus.empty()) return "auto";
  return std::to_string(gpus[size_t(local) % gpus.size()]);
}

// This process's peak resident memory (tests/mpi/rank_memory.py: a rank holds its slab).
long peakResidentMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return long(u.ru_maxrss) / 1024;  // KiB on Linux
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int run(const Options& o, MPI_Comm world) {
  int rank = 0, size = 1;
  MPI_Comm_rank(world, &rank);
  MPI_Comm_size(world, &size);
  const std::string ofRank = "rank " + std::to_string(rank + 1);

  // 1. How many slices, and which this rank owns: from a raw input's listing, else from the
  // whole volume (read by every rank: those readers have no slab read).
  std::string error;
  LoadOptions load;
  bool slabRead = false;
  std::optional<Volume> whole;
  int slices = 0;
  try {
    load = o.input.loadOptions();
    slabRead = !o.wholeVolume && hasSlabRead(o.input.input, load);
    if (slabRead) {
      slices = rawSlices(o.input.input, load);
    } else {
      whole = o.input.load();
      slices = whole->dims.z;
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!allSucceeded(world, error, "")) return 1;
  PartRange range;
  try {
    range = planParts(slices, std::vector<double>(size_t(size), 1.0), MultiDeviceOptions{}.apron)
                .at(size_t(rank));
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!allSucceeded(world, error, "")) return 1;

  // 2. This rank's slab (its range and apron) from disk.
  std::optional<Volume> slab;
  if (slabRead) {
    try {
      slab = readSlab(o.input.input, load, range);
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!allSucceeded(world, error, sliceText(range))) return 1;
    // The raw values' storage is chosen per slab: a rescale that differs between slabs (a
    // float or wide unsigned input) would map the ranks' tables apart. Then read it whole.
    double mine[2] = {slab->slope, slab->intercept}, lo[2], hi[2];
    MPI_Allreduce(mine, lo, 2, MPI_DOUBLE, MPI_MIN, world);
    MPI_Allreduce(mine, hi, 2, MPI_DOUBLE, MPI_MAX, world);
    if (lo[0] != hi[0] || lo[1] != hi[1]) {
      if (rank == 0)
        std::cerr << "voxray-mpi: the slabs' values are stored with different rescales; every "
                     "rank reads the whole volume instead\n";
      slab.reset();
      slabRead = false;
      try {
        whole = o.input.load();
      } catch (const std::exception& e) {
        error = e.what();
      }
      if (!allSucceeded(world, error, "")) return 1;
    }
  }
  // The whole volume's stored range (the tables map it): agreed over the slabs. VOLUME: the
  // whole volume's geometry; with a slab read, without voxels (the rank holds SLAB alone).
  std::optional<ValueRange> valueRange;
  Volume volume;
  if (slabRead) {
    const ValueRange mine = storedRange(*slab);
    int lo = mine.min, hi = mine.max;
    MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_INT, MPI_MIN, world);
    MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_INT, MPI_MAX, world);
    valueRange = ValueRange{int16_t(lo), int16_t(hi)};
    volume = slabGeometry(*slab, range, slices);
  } else {
    volume = std::move(*whole);
    whole.reset();
  }

  // 3. This rank's device and its part renderer.
  const std::string selector = deviceFor(o.device, world);
  std::unique_ptr<ClContext> context;
  std::unique_ptr<MultiDeviceRenderer> renderer;
  RenderParams p;
  std::vector<double> keys;
  try {
    p = o.flags.params();
    context = std::make_unique<ClContext>(selector);
    MultiDeviceOptions mo;
    mo.ranges = {range};
    mo.emptySpaceSkipping = o.ess == "on";
    mo.valueRange = valueRange;
    if (slab) {
      mo.slab = &*slab;
      mo.slabFirst = range.storedFirst;
    }
    renderer =
        std::make_unique<MultiDeviceRenderer>(std::vector<ClContext*>{context.get()}, volume, mo);
    keys = renderer->visibilityKeys(p);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!allSucceeded(world, error, sliceText(range))) return 1;
  {
    std::string held =
        std::to_string(range.storedFirst) + "-" + std::to_string(range.storedEnd - 1);
    const auto lines = gatherText(world, ofRank + ": " + context->device().name + ", " +
                                             sliceText(range) + " (held " + held + ", " +
                                             (slabRead ? "read alone" : "whole volume read") + ")");
    for (const auto& line : lines) std::cerr << "  " << line << "\n";
  }

  // 4. The composite order (dvr), the same on every rank: by the parts' visibility keys.
  std::vector<double> allKeys(static_cast<size_t>(size));
  MPI_Allgather(&keys[0], 1, MPI_DOUBLE, allKeys.data(), 1, MPI_DOUBLE, world);
  std::vector<int> order(static_cast<size_t>(size));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return allKeys[size_t(a)] < allKeys[size_t(b)]; });

  // 5. The frames: the first builds the kernels; with --frames N the rest are timed.
  IcetCompositor icet(world);
  const std::optional<NdcBox> bounds = slabBoundsNdc(volume, p, range);
  const IcetColour colour = o.icetColour == "bytes" ? IcetColour::Bytes : IcetColour::Floats;
  Image image;
  std::vector<double> frameMs, renderMs, compositeMs, ownMs, ownCompositeMs;
  std::vector<double> copyMs, compressMs, blendMs, collectMs, totalMs;
  for (int f = 0; f < std::max(o.frames, 1); ++f) {
    IcetFrameStats stats;
    MPI_Barrier(world);  // every rank starts the frame together: the time is the frame's
    icet.drawFrame(*renderer, p, order, bounds, colour, &image, &stats, &error);
    if (!allSucceeded(world, error, sliceText(range))) return 1;
    // The slowest rank's part bounds the frame. IceT's composite time on a faster rank holds
    // its wait for that part; on the slowest rank it is the composite alone.
    struct {
      double ms;
      int rank;
    } slowest{stats.renderMs, rank};
    MPI_Allreduce(MPI_IN_PLACE, &slowest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
    double composite = stats.compositeMs;
    MPI_Bcast(&composite, 1, MPI_DOUBLE, slowest.rank, world);
    if (f > 0 || o.frames <= 1) {
      frameMs.push_back(stats.frameMs);
      ownMs.push_back(stats.renderMs);
      ownCompositeMs.push_back(stats.compositeMs);
      copyMs.push_back(stats.copyMs);
      compressMs.push_back(stats.compressMs);
      blendMs.push_back(stats.blendMs);
      collectMs.push_back(stats.collectMs);
      totalMs.push_back(stats.icetTotalMs);
      renderMs.push_back(slowest.ms);
      compositeMs.push_back(composite);
    }
  }
  if (rank == 0) {
    std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode) << " on "
              << size << (size == 1 ? " rank" : " ranks") << ": frame " << median(frameMs)
              << " ms, slowest part " << median(renderMs) << " ms, IceT composite "
              << median(compositeMs) << " ms on the slowest part's rank ("
              << (o.frames > 1 ? "median of " + std::to_string(frameMs.size()) + " frames after one"
                               : std::string("first frame, includes the kernel builds"))
              << ")\n";
  }
  // Each rank's own part and IceT's composite time there (with its wait for slower parts).
  std::ostringstream own;
  own << "  " << ofRank << ": part " << median(ownMs) << " ms, IceT composite "
      << median(ownCompositeMs) << " ms (compress " << median(compressMs) << ", blend "
      << median(blendMs) << "), copy into IceT " << median(copyMs) << " ms, collect "
      << median(collectMs) << " ms, IceT's total " << median(totalMs) << " ms, peak resident "
      << peakResidentMiB() << " MiB";
  const auto partLines = gatherText(world, own.str());
  for (const auto& line : partLines) std::cerr << line << "\n";
  error.clear();
  if (rank == 0 && !o.output.empty()) {
    try {
      writeImage(o.output, image);
      std::cerr << "-> " << o.output << "\n";
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  return allSucceeded(world, error, "") ? 0 : 1;
}

}  // namespace
}  // namespace voxray::mpi

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  voxray::mpi::Options o;
  CLI::App app{
      "voxray-mpi: one frame over MPI ranks, each rendering its z slab of the volume on its own "
      "OpenCL device, composited by IceT; rank 0 writes the image (mpiexec -n N voxray-mpi ...)"};
  o.input.add(app);
  o.flags.add(app);
  app.add_option("-o,--output", o.output, "image file rank 0 writes (PNG, TIFF, EXR)");
  app.add_option("--device", o.device,
                 "auto, cpu, gpu or a device number for every rank (default: this host's GPUs "
                 "one per rank, else the CPU; $VOXRAY_DEVICE)");
  app.add_option("--frames", o.frames,
                 "render this many frames and report the medians of all but the first")
      ->check(CLI::Range(1, 10000));
  app.add_flag("--whole-volume", o.wholeVolume,
               "every rank reads the whole volume, also where it could read its slab alone");
  app.add_option("--ess", o.ess, "empty-space skipping on (the default) or off (heavy frames)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--icet-colour", o.icetColour,
                 "what IceT composites: float (premultiplied float RGBA, the default) or bytes "
                 "(8-bit: a quarter of the bytes, up to one level per rank from float)")
      ->check(CLI::IsMember({"float", "bytes"}));
  int rc = 0;
  try {
    app.parse(argc, argv);
    if (o.output.empty() && o.frames <= 1)
      throw CLI::RequiredError("-o,--output (or --frames N to time frames only)");
  } catch (const CLI::ParseError& e) {
    // Every rank parsed the same arguments: rank 0 speaks.
    if (rank == 0)
      rc = app.exit(e);
    else
      rc = e.get_exit_code();
    MPI_Finalize();
    return rc == 0 ? 0 : 2;
  }
  try {
    rc = voxray::mpi::run(o, MPI_COMM_WORLD);
  } catch (const std::exception& e) {
    // A bug (every expected failure is agreed on inside run): this rank cannot tell the
    // others, so it ends the job rather than leave them waiting.
    std::cerr << "voxray-mpi: rank " << rank + 1 << ": internal error: " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  MPI_Finalize();
  return rc;
}
