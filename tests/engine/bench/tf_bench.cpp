// Issue 35's measured goals on the CPU: the histogram of a 512x512x400 CT (goal <= 150 ms on
// two cores) and a transfer-function edit to its new lookup table (render table and table
// bake, part of the <= 20 ms edit budget). Usage: voxray_tf_bench [--benchmark_...]
#include <benchmark/benchmark.h>

#include <cstdint>

#include "frame_setup.h"  // engine-internal
#include "voxray/engine/volume_property.h"
#include "voxray/io/histogram.h"
#include "voxray/io/volume.h"

namespace {

// 512x512x400 voxels of a CT's spread: air, fat, soft tissue and bone with noise, by a
// fixed hash of the index (no two runs differ).
const voxray::Volume& ct() {
  static const voxray::Volume v = [] {
    voxray::Volume out;
    out.dims = {512, 512, 400};
    out.intercept = -1024.0;
    out.voxels.resize(out.voxelCount());
    for (size_t i = 0; i < out.voxels.size(); ++i) {
      uint32_t h = uint32_t(i) * 2654435761u;
      h ^= h >> 15;
      int base = (h & 3u) == 0 ? 0 : (h & 3u) == 1 ? 930 : (h & 3u) == 2 ? 1064 : 2024;
      out.voxels[i] =
          int16_t(base + int((h >> 8) % 61u) - 30 + ((h & 3u) == 3 ? int((h >> 16) % 800u) : 0));
    }
    return out;
  }();
  return v;
}

void BM_Histogram512x512x400(benchmark::State& state) {
  const voxray::Volume& v = ct();
  for (auto _ : state) {
    voxray::StoredHistogram h = voxray::storedHistogram(v);
    benchmark::DoNotOptimize(h.counts.data());
  }
  state.counters["Mvoxels"] = double(v.voxelCount()) / 1e6;
}

// One drag step of the editor: a point moved, the render table made, the lookup table baked.
void BM_TfEditToLookupTable(benchmark::State& state) {
  const voxray::Volume& v = ct();
  voxray::VolumeProperty vp;
  vp.curve = state.range(0) ? voxray::TfCurve::Smooth : voxray::TfCurve::Linear;
  vp.color = {{-1000, {0, 0, 0}}, {-100, {0.8, 0.5, 0.4}}, {300, {1, 0.9, 0.8}}, {1500, {1, 1, 1}}};
  vp.opacity = {{-1000, 0}, {-200, 0}, {100, 0.2}, {400, 0.6}, {1500, 0.8}, {3000, 0.9}};
  voxray::RenderParams p;
  // The value range is found once per volume (DeviceFrame::valueRange), as the raycaster does.
  const voxray::ValueRange range = voxray::storedRange(v);
  int k = 0;
  for (auto _ : state) {
    vp.opacity[2].x = 100.0 + double(k++ % 50);  // as a drag does
    voxray::applyVolumeProperty(p, vp);
    voxray::FrameSetup s = voxray::makeValueSetup(v, voxray::setupKeyOf(p), range);
    benchmark::DoNotOptimize(s.lut.rgba.data());
  }
}

}  // namespace

BENCHMARK(BM_Histogram512x512x400)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TfEditToLookupTable)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
