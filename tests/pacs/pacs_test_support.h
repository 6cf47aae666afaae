#pragma once
// What the PACS tests share: a started Orthanc holding the shared series, volume comparison
// against the same files opened from disk, and a cache in a temporary folder.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "orthanc_server.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/pacs_cache.h"

namespace voxray::test {

inline std::string dicomPath(const std::string& rel) {
  return std::string(VOXRAY_DATA_DIR) + "/dicom/" + rel;
}

// The Philips phantom volume (28 CT slices), and the study's UIDs.
constexpr const char* kPhantomStudy =
    "1.3.46.670589.33.1.27492712521914879309.27169771283235650014";
constexpr const char* kPhantomSeries =
    "1.3.46.670589.33.1.6002432791750815306.26862469513794233732";

// An Orthanc holding the Philips phantom study, for the QTest classes. Throws (fails the
// test) with the reason when it does not start.
inline std::unique_ptr<OrthancServer> phantomServer() {
  auto server = std::make_unique<OrthancServer>();
  server->upload(dicomPath("ct-philips-phantom"));
  return server;
}

// FNV-1a over the stored voxels: equal volumes, equal sums.
inline uint64_t voxelChecksum(const Volume& v) {
  uint64_t h = 1469598103934665603ull;
  for (int16_t s : v.voxels) {
    h = (h ^ uint16_t(s)) * 1099511628211ull;
  }
  return h;
}

// A retrieved series must import exactly as the same files opened from disk.
inline void expectSameVolume(const Volume& retrieved, const Volume& disk) {
  EXPECT_EQ(retrieved.dims, disk.dims);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(retrieved.spacingMm[a], disk.spacingMm[a], 1e-9);
    EXPECT_NEAR(retrieved.originMm[a], disk.originMm[a], 1e-9);
  }
  EXPECT_EQ(retrieved.toPhysical(storedRange(retrieved).min),
            disk.toPhysical(storedRange(disk).min));
  EXPECT_EQ(retrieved.toPhysical(storedRange(retrieved).max),
            disk.toPhysical(storedRange(disk).max));
  EXPECT_EQ(voxelChecksum(retrieved), voxelChecksum(disk));
  EXPECT_EQ(retrieved.study.seriesInstanceUid, disk.study.seriesInstanceUid);
}

inline std::string failure(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an Error";
  return {};
}

inline std::string echoFailure(const PacsNode& node) {
  return failure([&] { makePacsClient(node)->echo(); });
}

inline std::vector<PacsMatch> findByName(PacsClient& client, const std::string& name) {
  PacsQuery q;
  q.patientName = name;
  return client.find(q);
}

// Name, date and modality searches on the two uploaded studies (Philips phantom: HEAD,
// 2015-02-06, 3 series of 28 + 1 + 6 images; GE tilt: REMOVED, no date, 28 images).
inline void expectStudyQueries(const PacsNode& node) {
  auto client = makePacsClient(node);
  auto head = findByName(*client, "HEAD");
  ASSERT_EQ(head.size(), 1u);
  EXPECT_EQ(head[0].studyInstanceUid, kPhantomStudy);
  EXPECT_EQ(head[0].studyDate, "20150206");
  EXPECT_EQ(head[0].numberOfSeries, 3);
  EXPECT_EQ(head[0].numberOfInstances, 28 + 1 + 6);
  auto tilt = findByName(*client, "REM*");
  ASSERT_EQ(tilt.size(), 1u);
  EXPECT_EQ(tilt[0].numberOfInstances, 28);
  PacsQuery q;
  q.dateFrom = "20150101";
  q.dateTo = "20151231";
  auto in2015 = client->find(q);
  ASSERT_EQ(in2015.size(), 1u);
  EXPECT_EQ(in2015[0].studyInstanceUid, kPhantomStudy);
  q = {};
  q.modality = "CT";
  EXPECT_EQ(client->find(q).size(), 2u);
  q.modality = "MR";
  EXPECT_EQ(client->find(q).size(), 0u);
}

inline void expectRetrievalMatchesDisk(const PacsNode& node) {
  PacsCache cache(tempFolder("cache"));
  int lastReceived = 0, lastTotal = 0;
  RetrieveOptions options;
  options.progress = [&](const RetrieveProgress& p) {
    lastReceived = p.received;
    lastTotal = p.total;
  };
  auto client = makePacsClient(node);
  CachedSeries entry = cache.retrieve(*client, kPhantomStudy, kPhantomSeries, options);
  EXPECT_EQ(entry.images, 28);
  EXPECT_EQ(lastReceived, 28);
  // DIMSE says how many images are coming; WADO-RS does not (total 0: "not known").
  EXPECT_EQ(lastTotal, node.transport == PacsNode::Transport::Dimse ? 28 : 0);
  ASSERT_EQ(cache.entries().size(), 1u);
  Volume retrieved = loadVolume(entry.folder);
  Volume disk = loadVolume(dicomPath("ct-philips-phantom/S2010"));
  EXPECT_EQ(retrieved.dims, glm::ivec3(512, 512, 28));
  expectSameVolume(retrieved, disk);
}

// No series in the index, no folder staged or kept.
inline void expectNothingCached(const PacsCache& cache) {
  EXPECT_TRUE(cache.entries().empty());
  EXPECT_TRUE(std::filesystem::is_empty(cache.root() + "/staging"));
  EXPECT_TRUE(std::filesystem::is_empty(cache.root() + "/series"));
}

inline void expectCancelLeavesNothing(const PacsNode& node) {
  PacsCache cache(tempFolder("cache"));
  std::atomic<bool> cancel{false};
  RetrieveOptions options;
  options.cancel = &cancel;
  options.progress = [&](const RetrieveProgress& p) {
    if (p.received == 5) cancel = true;
  };
  auto client = makePacsClient(node);
  try {
    cache.retrieve(*client, kPhantomStudy, kPhantomSeries, options);
    ADD_FAILURE() << "a cancelled retrieval returned";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
  }
  expectNothingCached(cache);
}

class PacsTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      server_ = std::make_unique<OrthancServer>();
      server_->upload(dicomPath("ct-philips-phantom"));
      server_->upload(dicomPath("ct-ge-tilt"));
    } catch (const std::exception& e) {
      startError_ = e.what();
    }
  }
  static void TearDownTestSuite() { server_.reset(); }
  void SetUp() override {
    // Never skipped: a test that cannot start Orthanc fails with the reason.
    ASSERT_TRUE(server_) << "Orthanc did not start: " << startError_;
  }
  OrthancServer& server() { return *server_; }

  static inline std::unique_ptr<OrthancServer> server_;
  static inline std::string startError_;
};

}  // namespace voxray::test
