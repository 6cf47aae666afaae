#pragma once
// A 3D look for a volume whose values are not Hounsfield units. The presets, the iso
// threshold and the mip window a user keeps as preferences are in HU: on an MR (values
// 0 ... 300, or 1000 ... 5000), a PET or a raw or NIfTI volume of unknown modality, an iso
// threshold of 400 may lie above every voxel and the 3D view opens empty. Such a volume
// opens with a classification from its own value histogram instead, and the user's HU look
// is kept for the next CT.
#include <string>
#include <vector>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

// Its values are HU: a CT, or a volume of unknown modality whose unit says HU (raw data with
// the user's rescale to HU).
bool valuesAreHu(const Volume& v);

// The unit a readout puts after a value of V: "HU" when valuesAreHu, else the unit the
// source states ("MR signal (scanner units)"), or "value" when it states none. Never "HU"
// for an MR or an unscaled raw file.
std::string valueUnit(const Volume& v);
// valueUnit short enough for a control's suffix: a long one ("scanner units") is "value".
std::string valueUnitLabel(const Volume& v);

struct ValueLook {
  // Physical values at the 1st and the 99.5th percentile of the voxels: the background
  // and the bright end, past the few outliers an MR's edges and vessels bring.
  double low = 0.0, high = 0.0;
  // The iso surface and the start of the dvr ramp: a quarter of the way from low to high,
  // above an MR's background noise and below its tissue.
  double threshold = 0.0;
};
ValueLook valueLook(const Volume& v);

// P with LOOK's classification: the iso range from the threshold up, dvr a grey ramp from
// the threshold (transparent) to the bright end (white; no preset and no shift), the mip
// window over low ... high. The mode and everything else stay.
void applyValueLook(RenderParams& p, const ValueLook& look);

}  // namespace voxray
