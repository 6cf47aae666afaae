#pragma once
// A coarse level of a volume (issue 38 part 1): the image shown at once while the full
// volume is uploaded. FACTOR^3 voxels become one, their mean (a box filter): the mean of
// stored values is the mean of their HU (physical = stored * slope + intercept is linear), so
// presets and thresholds mean what they mean on the full volume, and a dvr of it is the full
// dvr seen a little blurred. A max filter would keep thin bright structures for mip but grow
// every bone and vessel by up to FACTOR - 1 voxels in iso and dvr, moving surfaces; the mean
// moves none (a surface's level crossing stays where the box average crosses it).
#include "voxray/io/volume.h"

namespace voxray {

// VOLUME's geometry and value mapping without its voxels (nor a copy of them on the way): dims,
// spacing, origin, direction, slope, intercept, unit, modality, window, SUV, time point and
// count, source type. Not the study identity or warnings.
Volume withoutVoxels(const Volume& volume);

// Dims ceil(n / FACTOR) per axis; spacing n * spacing / coarse dims, so that the coarse box
// is exactly the full volume's box (same corners in LPS) even where n is not a multiple of
// FACTOR (a partial cell at the far end averages the voxels it has). Everything but the
// voxels and geometry is copied (slope, intercept, unit, modality, window, identity).
// FACTOR 1 copies the volume. Throws Error (Input) for a factor below 1 or an empty volume.
Volume coarseLevel(const Volume& volume, int factor);

// The factor that brings VOLUME under MAXVOXELS voxels: 1, 2, 4 or 8 (8 when even that is
// larger).
int coarseFactorFor(const Volume& volume, size_t maxVoxels);

}  // namespace voxray
