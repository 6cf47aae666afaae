#pragma once
// Issue 37, reading in the workstation: the reading keys (layouts, W/L presets on 1–6, pages,
// tools, next/previous series), the keymap's validation, hanging protocols applied when a
// study opens, and the Results menu's files read back with DCMTK (the SR's values in mm and
// its image references, the KOS's referenced images = the slices marked with K, the CSV,
// the anonymised copy), never written into the data's folder and replaced only after yes.
// The tests, by feature: reading_keys_and_layouts_test.cpp, reading_hanging_rules_test.cpp,
// reading_series_cells_test.cpp, reading_drag_drop_test.cpp and reading_results_test.cpp;
// reading_test.cpp opens the window for each and holds the helpers declared here.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <QObject>
#include <QStringList>
#include <QWidget>

#include "window_fixture.h"

class DcmTagKey;
class QMimeData;

namespace voxray::ui {
class ReadingActions;
class ResultsActions;
}  // namespace voxray::ui

namespace voxray::ui::test {

inline const std::string kData = VOXRAY_DATA_DIR "/dicom/";
// Philips head CT, 28 slices of 512² at 0.451171875 mm ("STD BRAIN 5MM", CT).
inline const std::string kBrain = kData + "ct-philips-phantom/S2010";

// The folder NAME of this test process, emptied.
std::filesystem::path freshDir(const std::string& name);

// Every value of TAG anywhere in FILE (sequences included), as DCMTK reads it.
std::vector<std::string> valuesIn(const std::filesystem::path& file, const DcmTagKey& tag);

// A study of two series in FOLDER: the Philips head CT as it is ("STD BRAIN 5MM", 28 slices
// of 5 mm) and, made from it, every other slice as a second series ("T2 LIKE 10MM": its own
// Series Instance UID, number and SOP Instance UIDs; the same study and Frame of Reference),
// so that its slices are 10 mm apart. Returns the second series' UID ("" on failure).
std::string writeTwoSeriesStudy(const std::filesystem::path& folder);

// A series made from the Philips head CT's slices (every other one: the odd or the even
// instance numbers), with its own UIDs and its values shifted by HUSHIFT (its Rescale
// Intercept), so that each series' voxels tell it apart from the others'.
struct DerivedSeries {
  std::string description;
  int number = 0;
  bool odd = true;
  int huShift = 0;
};

// A study in FOLDER: the head CT as it is ("STD BRAIN 5MM", 28 slices of 5 mm) and each of
// DERIVED (14 slices of 10 mm; the same study and Frame of Reference). Returns the derived
// series' UIDs in DERIVED's order (empty on failure).
std::vector<std::string> writeStudy(const std::filesystem::path& folder,
                                    const std::vector<DerivedSeries>& derived);

// V's first voxel (0, 0, 0) in HU.
double firstVoxelHu(const Volume& v);
// What a series derived from BRAIN with SHIFT must hold there: BRAIN's voxel at the same
// patient position (its slice nearest to V's first one) plus SHIFT.
double derivedFirstVoxelHu(const Volume& brain, const Volume& v, int shift);

// A drag of M entering W, then dropped at its centre, as Qt delivers them; whether W took both.
bool dropOn(QWidget* w, const QMimeData* m);

// A wheel turn of NOTCHES (120 each) at the centre of W.
void wheel(QWidget* w, int notches);

class ReadingTest : public QObject {
  Q_OBJECT
 private slots:
  void init();
  void cleanup();
  // reading_keys_and_layouts_test.cpp
  void layoutKeysChangeTheGrid();
  void numberKeysSetTheWindowPresets();
  void pageKeysMoveByTenOrTheSlab();
  void toolKeysPickTheTool();
  void shortcutsDialogListsTheReadingKeys();
  void keymapFileChangesKeysAndADuplicateIsRefused();
  void nextAndPreviousSeriesKeys();
  void sessionKeepsTheLayoutAndTheNextStartRemembersIt();
  void readmeScreenshot();
  // reading_hanging_rules_test.cpp
  void matchingRuleAppliesItsWindowAndLayout();
  void ruleEditorNamesTheFieldAndSavesWhatValidates();
  void ruleSeriesPlacementLeavesAMissingSeriesEmptyAndTheSessionKeepsIt();
  void ruleShowsTwoSeriesSideBySideLinkedInPatientZ();
  // reading_series_cells_test.cpp
  void ruleShowsFourSeriesEachInItsCell();
  void showSeriesInThisViewOpensItBeside();
  // reading_drag_drop_test.cpp
  void seriesDroppedFromTheBrowserOpensInThatView();
  // reading_results_test.cpp
  void reportHoldsTheValuesInMmAndItsImages();
  void keyImagesAreTheSlicesMarkedWithK();
  void anonymisedExportOfTheSeries();
  void anonymiseDialogWritesTheChosenDatesAndAsksBeforeReplacing();
  void petSegmentShowsItsSuvPeakAndTheReportHoldsIt();
  void fileMenuOpensThePacsNodeEditor();

 private:
  // RULES (a hanging-protocols.json's text) as the rules of the fresh config folder NAME.
  void useRules(const std::string& name, const char* rules);
  void openBrain();
  // Keys reach the views' actions only with the window active and a view focused (the load's
  // progress box took the activation while it was up).
  void focusView(QWidget& view);

  // Runs FN on the modal dialog named NAME (or of type T) once it is up: polled, since the
  // click or trigger that opens it blocks in the dialog's own event loop.
  void whenModal(const QString& name, std::function<void(QWidget*)> fn) {
    pollModal([name](QWidget* w) { return w->objectName() == name; }, std::move(fn));
  }
  template <class T>
  void whenModal(std::function<void(T*)> fn) {
    pollModal([](QWidget* w) { return qobject_cast<T*>(w) != nullptr; },
              [fn](QWidget* w) { fn(qobject_cast<T*>(w)); });
  }
  void pollModal(std::function<bool(QWidget*)> match, std::function<void(QWidget*)> fn);

  PhantomWindow fixture_;
  MainWindow* window_ = nullptr;
  ReadingActions* reading_ = nullptr;
  ResultsActions* results_ = nullptr;
  QStringList errors_;
};

}  // namespace voxray::ui::test
