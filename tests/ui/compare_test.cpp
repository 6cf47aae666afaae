// The compare tests' fixture (compare_test.h): a window on the head phantom for each test, and
// the helpers the tests share.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QWheelEvent>

#include "camera_link.h"
#include "compare_test.h"
#include "compare_view.h"
#include "fusion_panel.h"
#include "session_state.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "time_panel.h"
#include "voxray/io/phantom_series.h"

using namespace voxray;
using namespace voxray::ui;

glm::dmat3 turnAboutZ(double degrees) {
  const double a = glm::radians(degrees);
  return glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0),
                    glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
}

void CompareTest::init() {
  QVERIFY(fixture_.start());
  errors_.clear();
  fixture_.window->setErrorSink(
      [this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
}

void CompareTest::cleanup() { fixture_.stop(); }

QTEST_MAIN(CompareTest)
