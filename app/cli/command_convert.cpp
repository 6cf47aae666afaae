// voxray-cli convert: any input Voxray reads out as an OME-Zarr pyramid (issue 38), for the
// workstation and for other OME-Zarr readers (napari, zarr-python, ITK, Neuroglancer). Raw
// inputs and OME-Zarr are read a chunk's depth of slices at a time as the pyramid is written,
// so a volume larger than the memory converts; the other formats are loaded whole first.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include "commands.h"
#include "input_options.h"
#include "progress.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/slice_source.h"
#ifdef VOXRAY_HAS_DICOM  // the PACS client's library, which reads OME-Zarr URLs too
#include "voxray/io/zarr_url.h"
#endif

namespace voxray::cli {

namespace {

struct ConvertOptions {
  std::string output, codec = "blosc-zstd";
  int zarrVersion = 2, chunk = 64, levels = 0;
  bool force = false;
};

bool endsWith(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

#ifdef VOXRAY_HAS_ZARR
// The input as the writer reads it: a raw file, slice folder or pattern (RawSliceReader) and an
// OME-Zarr level of int16 or 8-bit values (folder or URL) read a range of slices at a time,
// never whole; anything else loaded whole into HELD and read in place. What the streamed paths
// do not take (a time point, a database series) goes the whole way, which says what is wrong.
std::unique_ptr<SliceSource> openSource(const InputOptions& in, std::optional<Volume>& held) {
  const LoadOptions o = in.loadOptions();
  const bool plainInput = !in.input.empty() && in.input.rfind("db:", 0) != 0 &&
                          in.input.rfind("sample:", 0) != 0 && !o.timePoint;
  if (plainInput && o.raw) return rawSliceSource(in.input, *o.raw);
  if (plainInput && in.flags.empty()) {
#ifdef VOXRAY_HAS_DICOM
    if (isUrl(in.input))
      if (auto s = omeZarrSliceSource(zarrUrlStore(in.input), in.level)) return s;
#endif
    if (isOmeZarr(in.input))
      if (auto s = omeZarrSliceSource(zarrFolderStore(in.input), in.level)) return s;
  }
  held = in.load();
  return volumeSliceSource(*held);
}
#endif

int runConvert(const InputOptions& in, const ConvertOptions& o) {
#ifdef VOXRAY_HAS_ZARR
  std::string out = o.output;
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  if (!endsWith(out, ".zarr"))
    throw inputError("-o " + o.output + ": convert writes OME-Zarr; name the output X.ome.zarr");
  // Before a long load: the writer checks again.
  std::error_code ec;
  if (!o.force && std::filesystem::exists(std::filesystem::symlink_status(out, ec)))
    throw outputError(out + ": exists already; choose another name, or give --force to replace it");
  ZarrWriteOptions w;
  w.zarrVersion = o.zarrVersion;
  w.chunk = o.chunk;
  w.codec = parseZarrCodec(o.codec);
  w.levels = o.levels;
  w.force = o.force;
  w.progress = terminalProgress("writing");
  const auto start = std::chrono::steady_clock::now();
  std::optional<Volume> held;
  const std::unique_ptr<SliceSource> source = openSource(in, held);
  const auto opened = std::chrono::steady_clock::now();
  const ZarrWriteResult r = writeOmeZarr(*source, out, w);
  const auto end = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << "wrote " << out << ": OME-Zarr "
            << (o.zarrVersion == 2 ? "0.4 (Zarr v2)" : "0.5 (Zarr v3)") << ", " << r.dataType
            << ", " << o.codec << ", " << r.dims.size() << " levels:";
  for (const glm::ivec3& d : r.dims) std::cout << " " << d.x << "x" << d.y << "x" << d.z;
  std::cout << "\n" << r.chunks << " chunks, " << r.bytes << " bytes; ";
  if (held)
    std::cout << "input loaded whole in " << seconds(start, opened) << " s, written in ";
  else
    std::cout << "input opened in " << seconds(start, opened)
              << " s, streamed (a chunk's depth of slices at a time) and written in ";
  std::cout << seconds(opened, end) << " s\n";
  for (const std::string& warning : source->warnings()) std::cerr << "warning: " << warning << "\n";
  return 0;
#else
  (void)in;
  (void)o;
  throw inputError(
      "convert: this build of Voxray cannot write OME-Zarr (built with "
      "VOXRAY_WITH_ZARR=OFF)");
#endif
}

}  // namespace

Run addConvertCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert",
      "Write any input Voxray reads as an OME-Zarr pyramid (NGFF 0.4 on Zarr v2, 0.5 on v3). "
      "Raw files, slice folders and patterns, and OME-Zarr (int16 or 8-bit) are read a chunk's "
      "depth of slices at a time, in memory bounded by the slice size (a 2048x2048x1024 CT: "
      "under 1 GiB); DICOM, NIfTI, NRRD and MetaImage are loaded whole first");
  auto in = std::make_shared<InputOptions>();
  auto o = std::make_shared<ConvertOptions>();
  in->add(*cmd);
  cmd->add_option("-o,--output", o->output, "the new X.ome.zarr folder")->required();
  cmd->add_option("--zarr-version", o->zarrVersion, "2 (NGFF 0.4, the default) or 3 (NGFF 0.5)")
      ->check(CLI::IsMember({2, 3}));
  cmd->add_option("--chunks", o->chunk, "chunk edge in voxels (default 64)")
      ->check(CLI::Range(8, 512));
  cmd->add_option("--codec", o->codec, "chunk compression: blosc-zstd (default), zstd, gzip, none")
      ->check(CLI::IsMember({"blosc-zstd", "zstd", "gzip", "none"}));
  cmd->add_option("--levels", o->levels,
                  "pyramid levels with full resolution (default: halve until a slice fits one "
                  "chunk)")
      ->check(CLI::Range(1, 16));
  cmd->add_flag("--force", o->force, "replace the output if it exists");
  return [in, o] { return runConvert(*in, *o); };
}

}  // namespace voxray::cli
