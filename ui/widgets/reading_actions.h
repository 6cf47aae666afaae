#pragma once
// Reading → the keyboard's reading work (issue 37): layouts (Ctrl+1…6), W/L presets on 1–6,
// next/previous series of the study and study of the browser's list, paging by the slab or
// by 10, the measuring tools, and the hanging protocols that pick the layout, window and 3D
// preset when a study opens. Every key is a menu action (so Help → Keyboard shortcuts lists
// it) acting while the views have the focus, and comes from the keymap (keymap.json in the
// config folder). The rules and keys are reading_keymap.h's and hanging_protocol.h's.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QObject>
#include <QPointer>
#include <QString>

#include "app_models.h"
#include "hanging_protocol.h"
#include "layout_model.h"
#include "reading_keymap.h"
#include "series_cells.h"

class QAction;
class QMenu;
class QWidget;

namespace voxray::ui {

class LoadController;
class MainWindow;
class RenderScheduler;
class SliceView;
class VolumeView;
struct SeriesDrag;

class ReadingActions : public QObject {
  Q_OBJECT
 public:
  ReadingActions(MainWindow& window, AppModels& models);
  ~ReadingActions() override;

  // Where keymap.json and hanging-protocols.json live (the user's config folder, or one a
  // test sets); setConfigFolder reloads both.
  QString configFolder() const { return configFolder_; }
  void setConfigFolder(const QString& folder);
  QString hangingProtocolsPath() const;
  QString keymapPath() const;

  const ReadingKeymap& keymap() const { return keymap_; }
  const HangingProtocols& protocols() const { return protocols_; }
  // Binds A to the keymap's action ID (its key, and its key's context: the views).
  void bind(const std::string& id, QAction* a);
  QAction* action(const std::string& id) const;

  ViewLayout layout() const { return reading_.layout; }
  // The user's choice (a key, the menu): every view shows the open volume, and the layout is
  // remembered in the settings for the next start (used when no hanging protocol matches).
  void setLayout(ViewLayout l);
  // The layout and what a hanging protocol placed in each view (a session saves it).
  const ReadingLayout& reading() const { return reading_; }
  // Puts R on the grid: views left empty are hidden, their notes in the status bar.
  void setReading(const ReadingLayout& r);
  // A session's layout: its placement checked against the study's series first (a removed
  // series leaves its view empty); the notes of the views so emptied ("coronal: its series
  // 'T2' is no longer in the study; …"), for the session's message.
  std::vector<std::string> restoreReading(const ReadingLayout& r);
  // Show series in this view: S in VIEW; a series other than the open one shows beside it
  // (compare's two columns, linked in patient coordinates).
  void showSeriesInView(GridView view, const StudySeries& s);
  // A series dragged from the study browser and dropped on VIEW: on the grid's first cell (the
  // main one) or compare's left column it opens as the main document; on another cell of the
  // grid it shows beside as showSeriesInView does (a series of another study: in compare's
  // right column); on compare's right column it opens there. The other column is kept.
  void dropSeries(QWidget* view, const SeriesDrag& d);
  // More than two series placed: the cells of the views showing another series than the
  // main document's (series_cells.h), and each one's view in that view's grid position: an
  // axial slice view of its own series (cellView; none: the view has no cell), or in the 3D
  // view's place its series in 3D (cell3dView, with its own render thread).
  const SeriesCells& seriesCells() const { return *cells_; }
  SliceView* cellView(GridView view) const;
  VolumeView* cell3dView() const;
  RenderScheduler* cell3dScheduler() const { return cell3dScheduler_.get(); }
  // The open study's volume series in the study's order (none: no DICOM folder).
  std::vector<StudySeries> studySeries() const;
  // The view the last focused slice view is (axial before any).
  GridView focusedGridView() const;
  // The slice view last focused (axial before any).
  SliceView& focusedSlice() const;
  // The rule matching the open study applied (layout, window, 3D preset); its name, or "".
  QString applyHangingProtocol();
  void setProtocolsJson(const std::string& json);  // parse, save, use; throws Error
  void showHangingProtocolEditor();
  void showKeymapEditor();

  void stepSeries(int step);  // +1 next, -1 previous
  void stepStudy(int step);
  void page(int direction);  // +1 forward

 signals:
  void failed(const QString& title, const QString& message);
  void layoutChanged();
  void protocolApplied(const QString& ruleName);

 private:
  void buildMenu();
  void applyKeys();
  void loadUserFiles();
  void status(const QString& text);
  // The rule's series placement for the open study: opens the series its first view holds
  // when another is open (the placement is put on once it is shown). False: the rule places
  // no series, or the study is no DICOM folder.
  bool placeSeriesOf(const HangingRule& r);
  QString applyLook(const HangingRule* r);  // the rule's window and 3D preset, said
  QString emptyViewsText() const;           // "Views left empty: sagittal: …", or ""
  // PLACED on the grid with CURRENT (the open series) shown: a second series opens beside it
  // in compare's right column; with more than two series each other series opens in a cell
  // of its own in its view's place (series_cells.h).
  void hang(ReadingLayout placed, const std::string& current);
  // The cells reading_ needs with CURRENT as the main document's series: kept, opened
  // (each series loads from the study's folder) or closed.
  void showCells(const std::string& current);
  void closeCell(GridView view);
  std::string openSeriesSelector() const;  // the open series' selector, or ""
  void fillSeriesMenu(QMenu* menu);

  MainWindow& window_;
  AppModels& models_;
  QString configFolder_;
  ReadingKeymap keymap_;
  HangingProtocols protocols_;
  std::map<std::string, QAction*> actions_;
  ReadingLayout reading_;
  // A rule's placement waiting for its series to be shown (placeSeriesOf opened it).
  std::optional<ReadingLayout> pendingPlacement_;
  std::optional<HangingRule> pendingRule_;
  int focusedSlice_ = 0;
  // The placement opened its second series as compare's prior (a layout key closes it).
  bool besideShown_ = false;
  // More than two series: the cells (their models), their views and loaders, and the study
  // folder they were opened from (another study closes them).
  std::unique_ptr<SeriesCells> cells_;
  std::map<GridView, QPointer<SliceView>> cellViews_;
  std::map<GridView, QPointer<LoadController>> cellLoaders_;
  std::unique_ptr<RenderScheduler> cell3dScheduler_;  // the 3D cell's, before its models go
  QPointer<VolumeView> cell3d_;
  std::string cellsFolder_;
};

// Qt's reading of a key text ("ctrl+n" → "Ctrl+N"); "" when it is no key.
std::string qtKeyNormaliser(const std::string& key);

}  // namespace voxray::ui
