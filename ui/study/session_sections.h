#pragma once
// The session file's sections, each written and read in a file of its own (session*.cpp only):
// the input (session_input.cpp), the render parameters, slice views and overlays
// (session_views.cpp), the reading layout (session_reading.cpp), the fusion overlay
// (session_fusion.cpp) and compare's prior (session_comparison.cpp); session.cpp writes and
// reads the file in their order.
#include <array>
#include <string>
#include <vector>

#include "session.h"
#include "session_reader.h"

namespace voxray::session_detail {

// session_input.cpp
Json inputJson(const SessionInput& in, const std::string& sessionPath);
// An input object (the study's "input", the overlay's "fusion.input"), FIELD naming it: its
// path resolved beside the session first (a folder moved with its session), then where it was
// saved; MISSING lists the paths tried when it is at none.
void readInputObject(Reader& r, const Json& in, const std::string& field,
                     const std::string& sessionPath, SessionInput& out,
                     std::vector<std::string>& missing);
void readInput(Reader& r, const Json& root, const std::string& sessionPath, SessionRead& out);

// session_views.cpp
void readRender(Reader& r, const Json& root, RenderParams& p);
// The views that are turned or thick, by name; absent views are acquisition planes, thin.
Json viewsJson(const std::array<SessionView, 3>& views);
void readViews(Reader& r, const Json& slices, Session& s);
// Sessions before the overlays were saved lack the object, or a key of it: the defaults.
void readOverlays(Reader& r, const Json& root, ViewOverlays& o);

// session_reading.cpp
Json readingJson(const ReadingLayout& l);
void readReading(Reader& r, const Json& root, Session& s);

// session_fusion.cpp
Json fusionJson(const Session::Fusion& f, const std::string& sessionPath);
void readFusion(Reader& r, const Json& root, const std::string& sessionPath, SessionRead& out);
// An optional time point (a 4D overlay's or prior's own) at KEY of J, FIELD naming it.
int readTimePoint(Reader& r, const Json& j, const char* key, const std::string& field);

// session_comparison.cpp: compare's prior (S.comparison), its alignment and 3D camera
Json comparisonJson(const Session& s);
void readComparison(Reader& r, const Json& root, Session& s);

}  // namespace voxray::session_detail
