#include "bench_seed.h"

namespace voxray::cli {

const char* const kSeedSizes[4] = {"512x384", "640x480", "800x600", "1024x768"};

std::vector<SeedDataset> seedDatasets(const std::string& dataDir) {
  std::vector<SeedDataset> out(3);
  SeedDataset& head = out[0];
  head.name = "Head";
  head.input.input = dataDir + "/stanford/CThead";
  head.input.flags = {{"raw-dims", "256,256"},  {"raw-type", "i16"},        {"raw-endian", "big"},
                      {"raw-spacing", "1,1,2"}, {"raw-rescale", "1,-1024"}, {"raw-axes", "LPI"}};
  head.isoHu = 400;  // bone
  head.seedCentral[0] = 27.02, head.seedCentral[1] = 24.39;
  head.seedCentral[2] = 20.40, head.seedCentral[3] = 14.08;
  head.seedZucker[0] = 18.51, head.seedZucker[1] = 15.38;
  head.seedZucker[2] = 11.62, head.seedZucker[3] = 7.87;

  SeedDataset& brain = out[1];
  brain.name = "Brain";
  brain.input.input = dataDir + "/stanford/MRbrain";
  brain.input.flags = {{"raw-dims", "256,256"},
                       {"raw-type", "u16"},
                       {"raw-endian", "big"},
                       {"raw-spacing", "1,1,1.5"},
                       {"raw-axes", "PIL"}};
  brain.isoHu = 1600;  // scanner units: skin and brain surface above the background (~1028)
  brain.seedCentral[0] = 30.30, brain.seedCentral[1] = 27.02;
  brain.seedCentral[2] = 23.25, brain.seedCentral[3] = 16.39;
  brain.seedZucker[0] = 23.25, brain.seedZucker[1] = 19.60;
  brain.seedZucker[2] = 16.39, brain.seedZucker[3] = 11.76;

  // The stent's spacing is not known here: 1 x 1 x 1 mm is assumed.
  SeedDataset& stent = out[2];
  stent.name = "Stent";
  stent.input.input = dataDir + "/raw/stent/stent_128x128x256_u8.raw";
  stent.input.flags = {{"raw-dims", "128,128,256"},
                       {"raw-type", "u8"},
                       {"raw-spacing", "1,1,1"},
                       {"raw-rescale", "62.5,0"}};
  stent.isoHu = 1000;  // the stent and contrast-filled vessels
  stent.seedCentral[0] = 15.87, stent.seedCentral[1] = 12.56;
  stent.seedCentral[2] = 9.90, stent.seedCentral[3] = 7.46;
  stent.seedZucker[0] = 6.53, stent.seedZucker[1] = 4.90;
  stent.seedZucker[2] = 3.62, stent.seedZucker[3] = 2.69;
  return out;
}

}  // namespace voxray::cli
