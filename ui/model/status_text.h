#pragma once
// The frame statistics and device as the status bar and the window title show them (the
// seed put fps and device in the title; the issue asks for both places).
#include <string>

#include "no_qt.h"

namespace voxray::ui {

struct FrameStats {
  bool any = false;  // false until the first frame
  double fps = 0.0;
  double lastMs = 0.0;
  bool interactive = false;
};

// "12.5 fps · 80 ms", "12.5 fps · 80 ms (interactive)", "80 ms" after the first frame
// (no rate yet) or "no frame yet".
std::string formatFrameStats(const FrameStats& s);

// "NAME — 12.5 fps · 80 ms — DEVICE — Voxray"; parts that are not known yet are left out.
// NAME is the document name (a file or folder name, never patient data).
std::string formatWindowTitle(const std::string& name, const FrameStats& s,
                              const std::string& device);

}  // namespace voxray::ui
