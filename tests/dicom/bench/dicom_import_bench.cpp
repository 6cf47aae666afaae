// Seconds to a device-ready volume for the generated 512x512x500 series
// (run voxray_make_bench_series first). Usage: voxray_dicom_bench [--benchmark_...]
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "voxray/io/dicom_import.h"

namespace {

std::string benchDir(const char* variant) {
  const char* root = std::getenv("VOXRAY_BENCH_DIR");
  return std::string(root ? root : "/tmp/voxray-bench") + "/" + variant;
}

void importSeries(benchmark::State& state, const char* variant) {
  const std::string dir = benchDir(variant);
  if (!std::filesystem::exists(dir)) {
    state.SkipWithError("no benchmark series: run voxray_make_bench_series first");
    return;
  }
  size_t bytes = 0;
  for (auto _ : state) {
    voxray::Volume v = voxray::importDicom(dir);
    bytes = v.byteSize();
    benchmark::DoNotOptimize(v.voxels.data());
  }
  state.counters["MB"] = double(bytes) / (1 << 20);
}

void BM_DicomImportUncompressed(benchmark::State& s) { importSeries(s, "uncompressed"); }
void BM_DicomImportJpegLossless(benchmark::State& s) { importSeries(s, "jpeg-lossless"); }
void BM_DicomListOnly(benchmark::State& state) {
  const std::string dir = benchDir("uncompressed");
  if (!std::filesystem::exists(dir)) {
    state.SkipWithError("no benchmark series: run voxray_make_bench_series first");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(voxray::listDicomSeries(dir).series.size());
}

BENCHMARK(BM_DicomImportUncompressed)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_DicomImportJpegLossless)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_DicomListOnly)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
