// OME-Zarr over HTTP: a real server on loopback (Python's http.server from the venv, serving a
// folder `voxray-cli convert` wrote) and Voxray reading it by URL through the PACS client's
// HTTP session. The remote volume equals the local one voxel for voxel (Zarr v2 and v3), a
// level's load requests that level's chunks and no other's, a deleted chunk reads as the fill
// value with one warning, and HTTP failures name the URL's host without its credentials.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "http_folder_server.h"
#include "voxray/io/zarr_url.h"
#include "zarr_test_support.h"

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

namespace voxray::test {
namespace {

// The phantom at 48^3 in chunks of 16: levels 48^3 (27 chunks), 24^3 (8), 12^3 (1).
constexpr int kSize = 48, kChunk = 16;

// Runs voxray-cli with ARGS; stdout and stderr in OUTPUT; its exit status.
int runCli(const std::string& args, std::string& output) {
  TempDir scratch;
  const std::string log = scratch.file("out.txt");
  const int rc = std::system(("'" VOXRAY_CLI "' " + args + " > '" + log + "' 2>&1").c_str());
  std::ifstream in(log);
  output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

void expectSameVolume(const Volume& remote, const Volume& local) {
  ASSERT_EQ(remote.dims, local.dims);
  expectNear(remote.spacingMm, local.spacingMm, "spacing");
  expectNear(remote.originMm, local.originMm, "origin");
  for (int c = 0; c < 3; ++c) expectNear(remote.direction[c], local.direction[c], "direction");
  EXPECT_EQ(remote.slope, local.slope);
  EXPECT_EQ(remote.intercept, local.intercept);
  EXPECT_EQ(remote.sourceType, local.sourceType);
  // Voxel for voxel: the same chunks through the same decoder.
  ASSERT_EQ(remote.voxels.size(), local.voxels.size());
  EXPECT_TRUE(std::equal(remote.voxels.begin(), remote.voxels.end(), local.voxels.begin()));
}

class OmeZarrUrl : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    name_ = "v" + std::to_string(GetParam()) + ".ome.zarr";
    std::string out;
    ASSERT_EQ(runCli("convert -o '" + dir_.file(name_) + "' --phantom-size " +
                         std::to_string(kSize) + " --chunks " + std::to_string(kChunk) +
                         " --zarr-version " + std::to_string(GetParam()),
                     out),
              0)
        << out;
    ASSERT_THAT(out, HasSubstr("3 levels: 48x48x48 24x24x24 12x12x12")) << out;
    ASSERT_TRUE(server_.started()) << server_.error();
  }
  std::string local() const { return dir_.file(name_); }
  std::string url() const { return server_.url(name_); }
  // A chunk's key (z, y, x) at LEVEL as this Zarr version names it.
  std::string chunkKey(int level, int z, int y, int x) const {
    return std::to_string(level) + (GetParam() == 3 ? "/c/" : "/") + std::to_string(z) + "/" +
           std::to_string(y) + "/" + std::to_string(x);
  }

  TempDir dir_;
  TempDir logDir_;
  std::string name_;
  HttpFolderServer server_{dir_.path().string(), logDir_.file("requests.txt")};
};

TEST_P(OmeZarrUrl, EveryLevelEqualsTheLocalFolderVoxelForVoxel) {
  for (int level = 0; level < 3; ++level) {
    LoadOptions o;
    o.level = level;
    const Volume remote = loadVolumeOrUrl(url(), o);
    EXPECT_EQ(remote.dims, glm::ivec3(kSize >> level)) << "level " << level;
    expectSameVolume(remote, loadVolume(local(), o));
    EXPECT_TRUE(remote.warnings.empty()) << remote.warnings.front();
  }
}

TEST_P(OmeZarrUrl, ALevelRequestsItsMetadataAndOnlyItsOwnChunks) {
  server_.takeRequests();
  LoadOptions o;
  o.level = 1;
  loadVolumeOrUrl(url(), o);
  std::vector<std::string> got = server_.takeRequests();
  // The group (v2: zarr.json is asked first and is absent), level 1's array metadata and its
  // 2 x 2 x 2 chunks: nothing of level 0 (27 chunks) or level 2.
  std::vector<std::string> want = {"/" + name_ + "/zarr.json"};
  if (GetParam() == 2) want.push_back("/" + name_ + "/.zattrs");
  want.push_back("/" + name_ + (GetParam() == 2 ? "/1/.zarray" : "/1/zarr.json"));
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) want.push_back("/" + name_ + "/" + chunkKey(1, z, y, x));
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

TEST_P(OmeZarrUrl, ADeletedChunkReadsAsTheFillValueWithOneWarning) {
  const Volume whole = loadVolume(local());
  ASSERT_TRUE(fs::remove(local() + "/" + chunkKey(0, 1, 1, 1)));
  const Volume remote = loadVolumeOrUrl(url());
  expectSameVolume(remote, loadVolume(local()));
  // The chunk's box is the fill value (0: Voxray writes fill_value 0); the rest is the scan.
  size_t inBox = 0, differ = 0;
  for (int z = 0; z < kSize; ++z)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const bool box = x / kChunk == 1 && y / kChunk == 1 && z / kChunk == 1;
        if (box) {
          inBox += remote.toPhysical(remote.at(x, y, z)) == 0.0;
        } else {
          differ += remote.at(x, y, z) != whole.at(x, y, z);
        }
      }
  EXPECT_EQ(inBox, size_t(kChunk * kChunk * kChunk));
  EXPECT_EQ(differ, 0u);
  const auto missing =
      std::count_if(remote.warnings.begin(), remote.warnings.end(),
                    [](const std::string& w) { return w.find("missing") != std::string::npos; });
  EXPECT_EQ(missing, 1);
  EXPECT_THAT(remote.warnings, ::testing::Contains("1 of 27 chunks are missing in " + url() +
                                                   "/0; they show the fill value 0"));

  // voxray-cli info says it once, too.
  std::string out;
  ASSERT_EQ(runCli("info '" + url() + "'", out), 0) << out;
  EXPECT_THAT(out, HasSubstr("warning: 1 of 27 chunks are missing in " + url() + "/0"));
  EXPECT_EQ(out.find("missing"), out.rfind("missing")) << out;
  EXPECT_THAT(out, HasSubstr("dims        48 x 48 x 48"));
}

// voxray-cli render of the URL writes the same image as of the folder: the same volume (on
// the same OpenCL device) renders the same pixels.
TEST_P(OmeZarrUrl, TheCliRendersTheUrlAsTheFolder) {
  std::string out;
  const std::string fromUrl = logDir_.file("url.png"), fromFolder = logDir_.file("folder.png");
  ASSERT_EQ(runCli("render '" + url() + "' --level 1 --size 96x96 -o '" + fromUrl + "'", out), 0)
      << out;
  ASSERT_EQ(runCli("render '" + local() + "' --level 1 --size 96x96 -o '" + fromFolder + "'", out),
            0)
      << out;
  const std::vector<uint8_t> a = readBytes(fromUrl), b = readBytes(fromFolder);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
}

TEST_P(OmeZarrUrl, AFailingServerIsNamedWithoutTheCredentials) {
  // http.server ignores the credentials; the message must not show them.
  const std::string url =
      "http://alice:s3cret@127.0.0.1:" + std::to_string(server_.port()) + "/status500/" + name_;
  const std::string message = errorMessage([&] { loadVolumeOrUrl(url); });
  EXPECT_THAT(message, HasSubstr("OME-Zarr GET http://127.0.0.1:" + std::to_string(server_.port()) +
                                 "/status500/" + name_ +
                                 "/zarr.json: HTTP 500: the server failed; try again later"));
  EXPECT_THAT(message, Not(HasSubstr("s3cret")));
  EXPECT_THAT(message, Not(HasSubstr("alice")));
}

TEST_P(OmeZarrUrl, AServerThatIsNotThereIsNamedWithWhatToDo) {
  int port = 0;
  {
    TempDir empty;
    HttpFolderServer gone(empty.path().string(), empty.file("log.txt"));
    ASSERT_TRUE(gone.started()) << gone.error();
    port = gone.port();
  }  // stopped: nothing listens at PORT now
  const std::string host = "127.0.0.1:" + std::to_string(port);
  const std::string message =
      errorMessage([&] { loadVolumeOrUrl("https://bob:pw123@" + host + "/" + name_); });
  EXPECT_THAT(message, HasSubstr("OME-Zarr GET https://" + host + "/" + name_ + "/zarr.json: "));
  EXPECT_THAT(message, HasSubstr(": check the URL and the network"));
  EXPECT_THAT(message, Not(HasSubstr("pw123")));
}

TEST_P(OmeZarrUrl, AUrlWithoutAnOmeZarrSaysSo) {
  const std::string message =
      errorMessage([&] { loadVolumeOrUrl(server_.url("nothing.ome.zarr")); });
  EXPECT_THAT(message, HasSubstr(server_.url("nothing.ome.zarr") +
                                 ": holds neither zarr.json (Zarr v3) nor .zattrs (Zarr v2)"));
}

INSTANTIATE_TEST_SUITE_P(ZarrVersions, OmeZarrUrl, ::testing::Values(2, 3), [](const auto& info) {
  return std::string(info.param == 2 ? "v2" : "v3");
});

}  // namespace
}  // namespace voxray::test
