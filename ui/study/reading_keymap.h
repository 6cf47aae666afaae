#pragma once
// The reading keys (layouts, W/L presets on 1–6, next/previous series and study, paging,
// measuring tools, key images) as data: each action's id, what the shortcuts dialog calls it
// and its key. The user's keymap (keymap.json in the config folder) changes keys by action
// id; a key given to two actions is refused, naming both.
#include <functional>
#include <string>
#include <vector>

#include "no_qt.h"

namespace voxray {

constexpr int kKeymapVersion = 1;

struct ReadingAction {
  std::string id;     // "next-series"
  std::string title;  // "Next series of the study"
  std::string key;    // Qt's portable key text: "N", "Shift+N", "Ctrl+1", "PgUp"
};

// Every reading action with its default key, in menu order.
const std::vector<ReadingAction>& defaultReadingActions();
// The W/L preset (windowLevelPresets() name) of "window-1" … "window-6".
const std::vector<std::string>& numberKeyWindows();

// Turns a key text into the form two equal keys share ("ctrl+n" and "Ctrl+N"); "" when the
// text is no key. The workstation passes Qt's parser; the default upper-cases and trims.
using KeyNormaliser = std::function<std::string(const std::string&)>;
std::string plainKeyNormaliser(const std::string& key);

class ReadingKeymap {
 public:
  ReadingKeymap();  // the defaults
  const std::vector<ReadingAction>& actions() const { return actions_; }
  const std::string& key(const std::string& id) const;  // "" for an unknown id

  // Sets ID's key (after checking as apply does). Throws Error (Input) for an unknown id, a
  // key that is none, or a key another action has ("'N' is already Next series …").
  void setKey(const std::string& id, const std::string& key,
              const KeyNormaliser& normalise = plainKeyNormaliser);

  // The keymap JSON: {"voxray-keymap": 1, "keys": {"next-series": "N", …}}; actions left out
  // keep their default keys. Throws Error (Input) naming the field for a bad file, leaving
  // the keymap as it was.
  void applyJson(const std::string& json, const KeyNormaliser& normalise = plainKeyNormaliser);
  std::string toJson() const;  // every action's key
  // applyJson of PATH's text; nothing when PATH does not exist. Errors start with PATH.
  void load(const std::string& path, const KeyNormaliser& normalise = plainKeyNormaliser);

 private:
  std::vector<ReadingAction> actions_;
};

// Slices a page moves: a slab view its thickness in slices (the next slab touches this one,
// at least 1), a thin view 10 (what the views did before the keys were configurable).
int pageSlices(double slabMm, double sliceSpacingMm);

// Throws Error (Input) when two of ACTIONS share a key, naming both (and the key), or one
// has a key the normaliser does not read.
void checkKeymap(const std::vector<ReadingAction>& actions, const KeyNormaliser& normalise);

}  // namespace voxray
