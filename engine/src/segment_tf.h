#pragma once
// Per-segment transfer functions (issue 35, RenderParams::segmentTfs; kernels/classification/
// segment_tf.cl): which labels have their own table in a frame, the tables baked on the volume
// table's entries (same stored-value mapping, so one lookup position serves both), and the
// macro cells those tables may show in. Shared by the raycaster and the reference renderer.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/segmentation.h"

namespace voxray {

struct LabelCells;
struct Volume;

// Per label 0 ... 255 its table's number 1, 2, ... (kernels: segment_table.h's y), 0: the
// volume's. A label has one where P is dvr without a 2D transfer function (whose table stays the
// volume's), P.segmentTfs gives it a table and a visible segment of SEGMENTS names it (an
// invisible segment is plain volume, as for its colour). Numbered in label order.
std::array<int, 256> segmentTfSlots(const std::vector<Segment>& segments, const RenderParams& p);
bool anySegmentTf(const std::array<int, 256>& slots);

// The tables of SLOTS, each with VOLUME_LUT's storedMin, scale and entry count, table s at
// index s - 1.
std::vector<Lut> bakeSegmentTfs(const std::array<int, 256>& slots, const RenderParams& p,
                                const Volume& v, const Lut& volumeLut);
// All of them one after another, as the kernels read them.
std::vector<glm::vec4> packSegmentTfs(const std::vector<Lut>& luts);

// Per macro cell 1 where a label present in it (CELLS) has its own table with an opacity above
// 0 at a value the cell can interpolate (MINMAX: the cell's min and max with its apron,
// kernels/empty_space/classify.cl's margin of half a stored unit and one entry) and an opacity
// factor above 0 in TABLE (segment_table.h). Such cells must not be leapt whatever the volume's
// table says there; empty when no label has a table.
std::vector<uint8_t> segmentTfCells(const LabelCells& cells, const std::vector<int16_t>& minMax,
                                    const std::array<int, 256>& slots, const std::vector<Lut>& luts,
                                    const std::vector<glm::vec4>& table);

// RenderParams::segmentTfs as text, "L:SPEC;L:SPEC" (segment-tf): SPEC a preset name
// (voxray-cli presets), a transfer-function file (.json or Slicer .vp, its render table) or
// points HU:R:G:B:A,... as --tf; "" or "off": none. Throws Error (Input) naming what is wrong.
std::map<int, std::vector<ControlPoint>> parseSegmentTfs(const std::string& text);
// Points for every label ("1:-1000:0:0:0:0,...;2:..."), which parseSegmentTfs reads back.
std::string formatSegmentTfs(const std::map<int, std::vector<ControlPoint>>& tfs);
// --tf's points text (render_params.cpp).
std::vector<ControlPoint> parseTfPoints(const std::string& s);
std::string formatTfPoints(const std::vector<ControlPoint>& points);

}  // namespace voxray
