// voxray-cli convert: any input Voxray reads out as an OME-Zarr pyramid (issue 38), for the
// workstation and for other OME-Zarr readers (napari, zarr-python, ITK, Neuroglancer).
#include <chrono>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "input_options.h"
#include "progress.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"

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
  const Volume v = in.load();
  const auto loaded = std::chrono::steady_clock::now();
  const ZarrWriteResult r = writeOmeZarr(v, out, w);
  const auto end = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << "wrote " << out << ": OME-Zarr "
            << (o.zarrVersion == 2 ? "0.4 (Zarr v2)" : "0.5 (Zarr v3)") << ", " << r.dataType
            << ", " << o.codec << ", " << r.dims.size() << " levels:";
  for (const glm::ivec3& d : r.dims) std::cout << " " << d.x << "x" << d.y << "x" << d.z;
  std::cout << "\n"
            << r.chunks << " chunks, " << r.bytes << " bytes; read " << seconds(start, loaded)
            << " s, written " << seconds(loaded, end) << " s\n";
  for (const std::string& warning : v.warnings) std::cerr << "warning: " << warning << "\n";
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
      "Write any input Voxray reads as an OME-Zarr pyramid (NGFF 0.4 on Zarr v2, 0.5 on v3)");
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
