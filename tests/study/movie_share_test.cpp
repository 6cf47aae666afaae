// The workstation's movie export on the 3D view's device volume (issue 40 item 6): an orbit's
// frames rendered through the render worker (RenderWorker::renderOnDevice) upload no second
// copy of the volume and are byte for byte the frames of a raycaster of the export's own.
#include <gtest/gtest.h>

#include "movie.h"
#include "movie_export.h"
#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

using namespace voxray;

TEST(MovieShare, OrbitFramesOnTheViewsDeviceVolumeAreTheOwnContextsFrames) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(48));
  RenderWorker worker("cpu", {});
  worker.setVolume(volume);
  MoviePlan plan;
  plan.frames = 3;
  plan.params.width = 40;
  plan.params.height = 30;
  plan.params.mode = Mode::Dvr;
  plan.params.lighting = Lighting::Shadows;  // the light grid too: the view may have held it
  // The first call waits for the worker's upload of the view's volume (setVolume).
  const Image warm = worker.renderOnDevice(plan.params, volume.get());
  ASSERT_EQ(warm.width, 40);
  const int before = deviceVolumeUploads();
  MovieFrames shared(*volume, plan,
                     [&](const RenderParams& p) { return worker.renderOnDevice(p, volume.get()); });
  std::vector<Image> onView;
  for (int k = 0; k < shared.count(); ++k) onView.push_back(shared.frame(k));
  EXPECT_EQ(deviceVolumeUploads(), before);  // no second copy
  ClContext ctx("cpu");
  MovieFrames own(*volume, &ctx, plan);
  EXPECT_EQ(deviceVolumeUploads(), before + 1);  // what the export did before
  ASSERT_EQ(own.count(), 3);
  for (int k = 0; k < own.count(); ++k) {
    const Image mine = own.frame(k);
    ASSERT_EQ(mine.rgba.size(), onView[size_t(k)].rgba.size());
    EXPECT_TRUE(mine.rgba == onView[size_t(k)].rgba) << "frame " << k;
  }
  EXPECT_TRUE(onView[0].rgba != onView[1].rgba);  // a third of a turn apart
}

TEST(MovieShare, AVolumeNotOnTheDeviceIsAnErrorNotAnUpload) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(32));
  const Volume other = makeHeadPhantom(24);
  RenderWorker worker("cpu", {});
  worker.setVolume(volume);
  RenderParams p;
  p.width = 16;
  p.height = 12;
  worker.renderOnDevice(p, volume.get());
  const int before = deviceVolumeUploads();
  try {
    worker.renderOnDevice(p, &other);
    ADD_FAILURE() << "rendered a volume that is not on the device";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    EXPECT_NE(std::string(e.what()).find("export again"), std::string::npos) << e.what();
  }
  EXPECT_EQ(deviceVolumeUploads(), before);
}
