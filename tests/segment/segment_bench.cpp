// The segment editor's operations on a 512x512x400 CT-like volume made here (no data file):
// air, a soft-tissue ellipsoid head with noise, a 7 mm skull shell, a brain. Goals (issue 34,
// 2 cores): seeded region <= 0.5 s, threshold slice preview <= 50 ms, a 20 mm dab <= 30 ms,
// a 2 mm margin and fill holes <= 2 s each.
// Run: build/bin/voxray_segment_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include <random>

#include <benchmark/benchmark.h>

#include "segment_itk.h"
#include "voxray/io/segment_edit.h"
#include "voxray/io/segment_ops.h"

namespace voxray {
namespace {

const Volume& ct() {
  static const Volume v = [] {
    Volume v;
    v.dims = {512, 512, 400};
    v.spacingMm = {0.7, 0.7, 0.8};
    v.voxels.resize(v.voxelCount());
    std::mt19937 random(34);
    std::normal_distribution<float> noise(0.0f, 15.0f);
    const glm::dvec3 c = glm::dvec3(v.dims) * v.spacingMm * 0.5;
    const glm::dvec3 radii(150.0, 170.0, 140.0);  // mm: the head's outer surface
    for (int z = 0; z < v.dims.z; ++z)
      for (int y = 0; y < v.dims.y; ++y)
        for (int x = 0; x < v.dims.x; ++x) {
          const glm::dvec3 p = glm::dvec3(x, y, z) * v.spacingMm - c;
          const double r = glm::length(p / radii);  // 1 at the skin
          double hu = -1000.0;
          if (r < 1.0) hu = 40.0;                          // scalp, soft tissue
          if (r < 0.94 && r > 0.89) hu = 1200.0;           // skull (about 7 mm)
          if (r <= 0.89) hu = 30.0;                        // brain
          if (r < 0.3 && std::abs(p.x) < 4.0) hu = 300.0;  // a contrast vessel
          v.voxels[v.index(x, y, z)] = int16_t(hu + (r < 1.0 ? noise(random) : 0.0f));
        }
    return v;
  }();
  return v;
}

// A voxel of the skull on the centre row.
glm::ivec3 skullSeed() {
  const Volume& v = ct();
  const int y = v.dims.y / 2, z = v.dims.z / 2;
  for (int x = 0; x < v.dims.x; ++x)
    if (v.at(x, y, z) > 700) return {x + 2, y, z};
  return {0, 0, 0};
}

void seedRegion(benchmark::State& state) {
  const Connectivity c = state.range(0) == 26 ? Connectivity::Full26 : Connectivity::Faces6;
  size_t voxels = 0;
  for (auto _ : state) {
    Mask m = seededRegion(ct(), {700, 3000}, skullSeed(), c);
    voxels = size_t(std::count(m.begin(), m.end(), uint8_t(1)));
    benchmark::DoNotOptimize(m.data());
  }
  state.counters["voxels"] = double(voxels);
}
BENCHMARK(seedRegion)->Arg(6)->Arg(26)->Unit(benchmark::kMillisecond)->UseRealTime();

void thresholdSlicePreview(benchmark::State& state) {
  for (auto _ : state) {
    Mask m =
        thresholdSlice(ct(), int(state.range(0)), ct().dims[int(state.range(0))] / 2, {700, 3000});
    benchmark::DoNotOptimize(m.data());
  }
}
BENCHMARK(thresholdSlicePreview)->Arg(2)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

void dab20mm(benchmark::State& state) {
  Segmentation s = emptySegmentation(ct());
  Segment seg;
  s.segments.push_back(seg);
  const glm::dvec3 centre(256, 256, 200);
  for (auto _ : state) {
    LabelPatch p = paintSphere(s, centre, 10.0, 1);  // 20 mm across
    state.PauseTiming();
    swapPatch(s, p);  // back to empty, so every dab paints the same voxels
    state.ResumeTiming();
  }
}
BENCHMARK(dab20mm)->Unit(benchmark::kMillisecond)->UseRealTime();

const Mask& skull() {
  static const Mask m = seededRegion(ct(), {700, 3000}, skullSeed(), Connectivity::Faces6);
  return m;
}

void margin2mm(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    Mask m = skull();
    state.ResumeTiming();
    applyMargin(gridOf(ct()), m, state.range(0) / 10.0);
  }
}
BENCHMARK(margin2mm)->Arg(20)->Arg(-20)->Unit(benchmark::kMillisecond)->UseRealTime();

void fillHolesOfSkull(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    Mask m = skull();
    state.ResumeTiming();
    fillHoles(gridOf(ct()), m);
  }
}
BENCHMARK(fillHolesOfSkull)->Unit(benchmark::kMillisecond)->UseRealTime();

// ITK's BinaryFillholeImageFilter on the whole volume (the hand-written fill works on the
// skull's box plus one voxel, about 70 % of it), for the choice of the hand-written fill
// (segment_ops.cpp).
void itkFillHolesOfSkull(benchmark::State& state) {
  const Volume& v = ct();
  for (auto _ : state) {
    state.PauseTiming();
    itk_ops::Block block{v.dims, v.spacingMm, skull()};
    state.ResumeTiming();
    itk_ops::fillHoles(block);
  }
}
BENCHMARK(itkFillHolesOfSkull)->Unit(benchmark::kMillisecond)->UseRealTime();

void keepLargestOfSkull(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    Mask m = thresholdMask(ct(), {700, 3000});
    state.ResumeTiming();
    keepLargestIsland(gridOf(ct()), m);
  }
}
BENCHMARK(keepLargestOfSkull)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace voxray

BENCHMARK_MAIN();
