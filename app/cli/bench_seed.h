#pragma once
// The seed paper's frame-rate table (GeForce 8800 GT, 2011; ../shared/peers/README.md),
// rerun on the shared data: first hit with central difference and Zucker-Hummel at the
// seed's four sizes, each cell printed beside the seed's figure.
#include <string>
#include <vector>

#include "bench_run.h"
#include "input_options.h"

namespace voxray::cli {

struct SeedDataset {
  std::string name;       // as in the seed's table
  InputOptions input;     // the file and raw layout under the data folder
  double isoHu = 0;       // first-hit threshold
  double seedCentral[4];  // fps at 512x384, 640x480, 800x600, 1024x768
  double seedZucker[4];
};

extern const char* const kSeedSizes[4];

// Head (CThead), Brain (MRbrain) and Stent, with paths under dataDir. The Bunny row has
// no data here and is left out.
std::vector<SeedDataset> seedDatasets(const std::string& dataDir);

}  // namespace voxray::cli
