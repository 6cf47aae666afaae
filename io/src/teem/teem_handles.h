#pragma once
// What io's NRRD reader and the segmentation's .seg.nrrd files share of Teem (libteem): its
// objects freed by the right call however a function leaves, and its error text made short.
// Header-only: the INTERFACE target voxray_teem (formats.cmake) carries it, with Teem.
#include <teem/nrrd.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace voxray::teem {

struct NrrdNix {  // frees the Nrrd but not its data (data we own, or Teem's, with nrrdNuke)
  void operator()(Nrrd* n) const { nrrdNix(n); }
};
struct NrrdNuke {  // frees the Nrrd and the data Teem allocated for it
  void operator()(Nrrd* n) const { nrrdNuke(n); }
};
struct IoNix {
  void operator()(NrrdIoState* s) const { nrrdIoStateNix(s); }
};

// Teem's own explanation of the last failure, its deepest cause (the last line) only;
// biffGetDone also clears it for the next call.
inline std::string reason() {
  char* text = biffGetDone(NRRD);
  std::string all = text ? text : "";
  std::free(text);
  while (!all.empty() && (all.back() == '\n' || all.back() == ' ')) all.pop_back();
  const size_t line = all.rfind('\n');
  std::string last = line == std::string::npos ? all : all.substr(line + 1);
  const size_t colon = last.find(": ");  // "[nrrd] _nrrdFunction: what went wrong"
  return colon == std::string::npos ? last : last.substr(colon + 2);
}

}  // namespace voxray::teem
