// Issue 35: the preset gallery's state (tf_gallery.h). Which presets (Voxray's dvr presets, the
// user's folder with its bad files named), which pictures are stale for the volume shown, the
// requests that render them, pictures kept per volume and preset, and the pictures rendered
// on the render thread behind the view's frames.
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <gtest/gtest.h>

#include "render_worker.h"
#include "tf_gallery.h"
#include "voxray/io/phantom.h"

using namespace voxray;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> namesOf(const std::vector<GalleryPreset>& ps) {
  std::vector<std::string> out;
  for (const GalleryPreset& p : ps) out.push_back(p.name);
  return out;
}

void writeText(const fs::path& f, const std::string& text) { std::ofstream(f) << text; }

struct TempDir {
  fs::path path =
      fs::temp_directory_path() /
      ("voxray_tfgallery_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
       "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

int differingPixels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return a.width * a.height;
  int n = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    n += !std::equal(a.rgba.begin() + long(i), a.rgba.begin() + long(i) + 4,
                     b.rgba.begin() + long(i));
  return n;
}

}  // namespace

TEST(TfGallery, BuiltinPresetsAreTheDvrPresetsWithTheirTables) {
  const std::vector<GalleryPreset> ps = builtinGalleryPresets();
  EXPECT_EQ(namesOf(ps),
            (std::vector<std::string>{"CT-Bone", "CT-Muscle", "CT-Skin", "MR-Default"}));
  for (const GalleryPreset& g : ps) {
    EXPECT_EQ(g.origin, "built-in");
    // A picture renders exactly the preset's table (a linear property on shared points).
    EXPECT_EQ(galleryParams(g.property, 96).transferFunction, findPreset(g.name).tf.points)
        << g.name;
  }
}

TEST(TfGallery, FolderPresetsAreReadAndBadFilesNamed) {
  TempDir dir;
  VolumeProperty mine = builtinGalleryPresets()[0].property;
  mine.name = "My bone";
  mine.opacity[1].opacity = 0.42;
  writeVolumePropertyFile(mine, (dir.path / "a_mine.json").string());
  VolumeProperty slicer = builtinGalleryPresets()[2].property;
  writeVolumePropertyFile(slicer, (dir.path / "b_slicer.vp").string());
  writeText(dir.path / "c_list.xml",
            R"(<PresetList><VolumeProperty name="A" interpolation="1" shade="1" ambient="0.1"
      diffuse="0.9" specular="0.2" specularPower="10" gradientOpacity="4 0 1 255 1"
      scalarOpacity="4 0 0 100 0.5" colorTransfer="4 0 1 0 0"/><VolumeProperty name="B"
      interpolation="1" shade="1" ambient="0.1" diffuse="0.9" specular="0.2" specularPower="10"
      gradientOpacity="4 0 1 255 1" scalarOpacity="4 -200 0 300 0.25"
      colorTransfer="4 0 0 0 1"/></PresetList>)");
  writeText(dir.path / "d_bad.vp",
            "1\n1\n0.9\n0.1\n0.2\n10\n4 0 0 100 1.5\n4 0 1 255 1\n4 0 1 1 1\n");
  writeText(dir.path / "notes.txt", "not a preset");
  fs::create_directories(dir.path / "sub");
  writeVolumePropertyFile(mine, (dir.path / "sub" / "deeper.json").string());

  const PresetFolder f = readPresetFolder(dir.path.string());
  // By file name; a .vp has no name: its file's stem.
  EXPECT_EQ(namesOf(f.presets), (std::vector<std::string>{"My bone", "b_slicer", "A", "B"}));
  EXPECT_EQ(f.presets[0].property, mine);
  EXPECT_EQ(f.presets[0].origin, (dir.path / "a_mine.json").string());
  EXPECT_EQ(f.presets[3].property.opacity[1], (OpacityNode{300.0, 0.25}));
  ASSERT_EQ(f.problems.size(), 1u);
  EXPECT_EQ(f.problems[0],
            (dir.path / "d_bad.vp").string() + ": opacity point 2 has 1.5; it must lie in 0 ... 1");
  // No folder (not made yet): no presets and nothing wrong.
  const PresetFolder none = readPresetFolder((dir.path / "missing").string());
  EXPECT_TRUE(none.presets.empty());
  EXPECT_TRUE(none.problems.empty());
}

TEST(TfGallery, StalePicturesAreRequestedAndKeptPerVolumeAndPreset) {
  TfGalleryModel m;
  int notified = 0;
  m.changed.connect([&] { ++notified; });
  m.setPresets(builtinGalleryPresets());
  EXPECT_TRUE(m.requests().empty());  // no volume: nothing to render
  EXPECT_EQ(m.staleCount(), 4u);

  auto v1 = std::make_shared<const Volume>(makeHeadPhantom(16));
  auto v2 = std::make_shared<const Volume>(makeHeadPhantom(16));
  m.setVolume(v1);
  std::vector<TfGalleryModel::Request> asked = m.requests();
  ASSERT_EQ(asked.size(), 4u);
  for (size_t i = 0; i < asked.size(); ++i) {
    EXPECT_EQ(asked[i].params.width, TfGalleryModel::kTileSize);
    EXPECT_EQ(asked[i].params.height, TfGalleryModel::kTileSize);
    EXPECT_EQ(asked[i].params.mode, Mode::Dvr);
    EXPECT_EQ(asked[i].params.transferFunction, renderTable(m.presets()[i].property));
  }
  Image picture(TfGalleryModel::kTileSize, TfGalleryModel::kTileSize);
  // A picture rendered from another volume (the render thread had moved on) is not taken.
  EXPECT_FALSE(m.deliver(asked[1].id, picture, v2.get()));
  EXPECT_FALSE(m.deliver(12345, picture, v1.get()));  // never asked
  const int before = notified;
  EXPECT_TRUE(m.deliver(asked[1].id, picture, v1.get()));
  EXPECT_EQ(notified, before + 1);
  EXPECT_FALSE(m.deliver(asked[1].id, picture, v1.get()));  // once
  EXPECT_FALSE(m.isStale(1));
  EXPECT_EQ(m.staleCount(), 3u);
  // Asked again: only the stale ones, and an earlier request is still taken.
  std::vector<TfGalleryModel::Request> again = m.requests();
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(again[0].params.transferFunction, asked[0].params.transferFunction);
  EXPECT_TRUE(m.deliver(asked[0].id, picture, v1.get()));
  EXPECT_EQ(m.staleCount(), 2u);

  // Another volume: all stale; back to the first: its pictures at once.
  m.setVolume(v2);
  EXPECT_EQ(m.staleCount(), 4u);
  EXPECT_EQ(m.requests().size(), 4u);
  m.setVolume(v1);
  EXPECT_EQ(m.staleCount(), 2u);
  EXPECT_EQ(m.cachedCount(), 2u);

  // An edited preset (a changed file) is another picture; the others keep theirs.
  std::vector<GalleryPreset> edited = builtinGalleryPresets();
  edited[1].property.opacity.back().opacity *= 0.5;
  edited[1] =
      GalleryPreset{edited[1].name, edited[1].origin, edited[1].property, edited[1].key + "edited"};
  m.setPresets(edited);
  EXPECT_TRUE(m.isStale(1));
  EXPECT_FALSE(m.isStale(0));

  // A volume that is gone takes its pictures with it.
  m.setVolume(v2);
  const std::vector<TfGalleryModel::Request> forV2 = m.requests();
  EXPECT_TRUE(m.deliver(forV2[2].id, picture, v2.get()));
  EXPECT_EQ(m.cachedCount(), 3u);
  m.setVolume(v1);
  v2.reset();
  m.setVolume(nullptr);
  EXPECT_EQ(m.cachedCount(), 2u);  // v1's two
  EXPECT_EQ(m.staleCount(), 4u);   // no volume shows
}

// The pictures on the render thread (RenderWorker::requestBackground), on PoCL: each is the
// frame the engine renders for its request, a view frame asked for with them comes first,
// and bone and skin look different on the phantom.
TEST(TfGallery, PicturesRenderBehindTheViewOnTheRenderThread) {
  std::mutex mutex;
  std::condition_variable arrived;
  std::vector<std::shared_ptr<const Frame>> frames;  // view and background, in order
  std::string error;
  RenderCallbacks cb;
  auto keep = [&](std::shared_ptr<const Frame> f) {
    std::lock_guard lock(mutex);
    frames.push_back(std::move(f));
    arrived.notify_all();
  };
  cb.frame = keep;
  cb.background = keep;
  cb.error = [&](const std::string& m, bool) {
    std::lock_guard lock(mutex);
    error = m;
    arrived.notify_all();
  };
  auto waitFor = [&](size_t n) {
    std::unique_lock lock(mutex);
    arrived.wait_for(lock, std::chrono::minutes(3),
                     [&] { return frames.size() >= n || !error.empty(); });
  };
  RenderWorker worker("cpu", cb);
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(48));
  TfGalleryModel m;
  m.setPresets(builtinGalleryPresets());
  m.setVolume(volume);
  std::vector<std::pair<int, RenderParams>> list;
  for (const TfGalleryModel::Request& r : m.requests()) list.emplace_back(r.id, r.params);
  ASSERT_EQ(list.size(), 4u);
  RenderParams view = list[0].second;
  view.width = 64;
  view.height = 48;
  // Both wait while the volume uploads: then the view first.
  worker.setVolume(volume);
  worker.requestBackground(list);
  worker.request(view, false);
  waitFor(5);
  ASSERT_EQ(error, "");
  ASSERT_EQ(frames.size(), 5u);
  EXPECT_EQ(frames[0]->tag, 0);
  EXPECT_EQ(frames[0]->image.width, 64);
  for (size_t i = 1; i < 5; ++i) {
    EXPECT_EQ(frames[i]->tag, list[i - 1].first);  // in order
    EXPECT_EQ(frames[i]->volume, volume.get());
    EXPECT_TRUE(m.deliver(frames[i]->tag, frames[i]->image, frames[i]->volume));
  }
  EXPECT_EQ(m.staleCount(), 0u);
  // The picture is the engine's frame for its request, pixel for pixel (no jitter).
  worker.request(list[2].second, false);
  waitFor(6);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(differingPixels(frames[5]->image, *m.picture(2)), 0);
  // CT-Bone and CT-Skin colour the head differently: most of the pixels the head covers
  // differ (half is a loose floor: the two share the background and the outline).
  int head = 0;  // pixels not background black
  for (size_t i = 0; i < m.picture(0)->rgba.size(); i += 4)
    head += m.picture(0)->rgba[i] + m.picture(0)->rgba[i + 1] + m.picture(0)->rgba[i + 2] > 0;
  const int differ = differingPixels(*m.picture(0), *m.picture(2));
  EXPECT_GT(head, 96 * 96 / 10) << head;  // the head is in the picture, not a speck
  EXPECT_GT(differ, head / 2) << differ << " of " << head;
  // An empty list cancels the pictures not yet started.
  worker.requestBackground(list);
  worker.requestBackground({});
  std::this_thread::sleep_for(std::chrono::seconds(2));
  std::lock_guard lock(mutex);
  EXPECT_LE(frames.size(), 7u);  // at most the one that had started
}
