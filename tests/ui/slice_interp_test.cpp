// The slice views' interpolation: the Slices panel's toggle switches the coronal view of
// thick slices between blocks (nearest) and a ramp (trilinear), at the physical aspect.
#include <set>

#include <QCheckBox>

#include "slice_view.h"
#include "study_state.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

constexpr int kSliceCount = 8;

// 32 x 32 columns of 1 mm pixels, 8 slices of 5 mm; each slice 100 HU above the one below.
std::shared_ptr<const Volume> thickSliceCount() {
  auto v = std::make_shared<Volume>();
  v->dims = {32, 32, kSliceCount};
  v->spacingMm = {1.0, 1.0, 5.0};
  v->modality = "CT";
  v->voxels.resize(v->voxelCount());
  for (int k = 0; k < kSliceCount; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) v->voxels[v->index(i, j, k)] = int16_t(100 * k);
  return v;
}

// The grey values down the image's middle column, top to bottom.
std::vector<int> middleColumn(const QImage& img) {
  std::vector<int> out;
  for (int y = 0; y < img.height(); ++y) out.push_back(qGray(img.pixel(img.width() / 2, y)));
  return out;
}

}  // namespace

class SliceInterpTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void toggleTurnsThickSliceStairsIntoARamp() {
    AppModels& m = *fixture_.models;
    openStudy(m, thickSliceCount(), "thick slices");
    m.windowLevel.set({800.0, 350.0});  // 0 ... 700 HU spread over the grey range
    auto* toggle = fixture_.window->findChild<QCheckBox*>("sliceInterp");
    QVERIFY(toggle);
    QVERIFY(toggle->isChecked());  // trilinear by default
    SliceView& coronal = fixture_.window->sliceView(1);
    // The physical aspect: 32 mm wide, 40 mm high in 1 mm pixels.
    QCOMPARE(coronal.sliceImage().size(), QSize(32, 40));
    const std::vector<int> linear = middleColumn(coronal.sliceImage());

    toggle->setChecked(false);
    QCOMPARE(m.render.sliceInterp(), Interp::Nearest);
    const std::vector<int> nearest = middleColumn(coronal.sliceImage());
    QCOMPARE(int(nearest.size()), 40);
    // Nearest: one grey per slice, each held for 5 rows (superior, the highest, on top).
    QCOMPARE(int(std::set<int>(nearest.begin(), nearest.end()).size()), kSliceCount);
    for (int y = 0; y < 40; ++y) {
      const int slice = kSliceCount - 1 - y / 5;
      QCOMPARE(nearest[size_t(y)], int(mapToGrey(100.0 * slice, m.windowLevel.value())));
    }
    // Trilinear: a ramp between slice centres, falling by 100 HU every 5 rows; the rows
    // at the slice centres (y = 2, 7, ...) keep the slice's own value.
    for (int y = 3; y < 37; ++y) {
      const double hu = 100.0 * ((kSliceCount - 1) - (y - 2) / 5.0);
      QCOMPARE(linear[size_t(y)], int(mapToGrey(hu, m.windowLevel.value())));
    }
    QVERIFY(std::set<int>(linear.begin(), linear.end()).size() > 30);
    QVERIFY(linear != nearest);

    toggle->setChecked(true);
    QCOMPARE(m.render.sliceInterp(), Interp::Linear);
    QCOMPARE(middleColumn(coronal.sliceImage()), linear);
  }
};

QTEST_MAIN(SliceInterpTest)
#include "slice_interp_test.moc"
