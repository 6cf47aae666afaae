// The switches of a kernel variant, declared once. Everything else is generated from this
// list: the -D options and the frame parameters' switch slots (engine/src/kernel_switches.cpp),
// the host's KernelSwitches struct, the variant names of tests and logs. The rules that set
// them from a frame's RenderParams and the raycaster's facts (storage, packets: KernelFacts)
// live in one function, kernelSwitches() (same file).
//
// VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS), KIND:
//   FRAME    a -D literal in a specialised kernel, so `if (SHADING)` folds away and only what
//            the frame uses is compiled; the uber kernel (RaycasterOptions::Kernel::Uber) reads
//            it from the frame parameters instead.
//   RUNTIME  always read from the frame parameters: compiling a program per value would buy
//            nothing (REFINE_STEPS bounds the bisection run once per hit ray).
//   BUILD    always a -D literal: it changes the kernel's arguments, stores or vector width.
// LABELS names the values for variant names, "|"-separated from 0; an empty label leaves the
// switch out of the name; no labels at all: NAME and the number, unless it is the default.
// GRADIENT is named only where SHADING, GRADIENT_OPACITY or TF2D is on (no other frame takes a
// gradient).
// Adding a switch: a line here, its rule in kernelSwitches(), the kernel code that uses it.
//
// VOXRAY_TUNING(NAME, AT_8_LANES, AT_16_LANES): the packets' measured tuning (the list at the
// end), not a choice of the frame: a -D literal in every PACKET variant, the value for its
// LANES; neither a slot, nor a field of KernelSwitches, nor part of the variant's name.
//
// Included by the kernels (params.cl) and by the engine; deliberately without a guard. An
// includer that leaves VOXRAY_TUNING undefined reads the switches only.
#ifndef VOXRAY_TUNING
#define VOXRAY_TUNING(NAME, AT_8_LANES, AT_16_LANES)
#define VOXRAY_TUNING_UNSET
#endif

// 0 iso (first hit of a HU range, refined by bisection, shaded), 1 dvr (front-to-back
// emission-absorption, the seed's transparency formula), 2 mip.
VOXRAY_SWITCH(MODE, 0, FRAME, "iso|dvr|mip")
// Blinn-Phong from the gradient (never for mip).
VOXRAY_SWITCH(SHADING, 0, FRAME, "|shaded")
// The gradient operator when shading: central differences, Sobel 3D, Zucker-Hummel.
VOXRAY_SWITCH(GRADIENT, 0, FRAME, "central|sobel|zh")
// 0 nearest voxel, 1 trilinear.
VOXRAY_SWITCH(INTERP, 1, FRAME, "nearest|")
VOXRAY_SWITCH(ORTHO, 0, FRAME, "|ortho")
// dvr: opacity scaled to the step (the preset's opacities are per voxel spacing).
VOXRAY_SWITCH(OPACITY_CORRECTION, 0, FRAME, "|oc")
// Each ray's samples shifted by a per-pixel fraction of a step (jitter_hash.h).
VOXRAY_SWITCH(JITTER, 0, FRAME, "|jitter")
// Empty-space skipping over macro cells (skip.cl).
VOXRAY_SWITCH(ESS, 0, FRAME, "|ess")
// iso: bisection steps refining a hit.
VOXRAY_SWITCH(REFINE_STEPS, 0, RUNTIME, "")
// The volume as image3d_t (GPUs, hardware filtering) instead of a buffer of shorts.
VOXRAY_SWITCH(STORAGE_IMAGE, 0, BUILD, "|image")
// The volume in this many z slabs, one argument each (slabs.cl).
VOXRAY_SWITCH(SLABS, 1, BUILD, "")
// Each ray's samples added to one of 64 counters (FrameStats::samples).
VOXRAY_SWITCH(COUNT_SAMPLES, 0, BUILD, "|counted")
// iso and dvr: each pixel's hit point to an extra output (march_iso, hit_output.cl).
VOXRAY_SWITCH(HIT_OUTPUT, 0, BUILD, "|hits")
// CPUs: a work-item marches LANES rays in SIMD (march/*_packet.cl); LANES 8 (4x2) or 16 (4x4).
VOXRAY_SWITCH(PACKET, 0, BUILD, "|packet")
VOXRAY_SWITCH(LANES, 8, BUILD, "")
// Lighting beyond Phong (issue 15): 0 phong, 1 shadows (diffuse and specular times the
// transmittance toward the light), 2 ao (ambient times the ambient visibility), both read
// from the light grid that rides behind the table in its buffer (light_volume.cl).
VOXRAY_SWITCH(LIGHTING, 0, FRAME, "|shadows|ao")
// dvr: segments of 2 or 4 steps in macro cells whose table varies within the frame's bound
// (RenderParams::adaptiveError, classify.cl's adaptive_level); set only with ESS, whose
// macro cells hold the levels. BUILD: its code is compiled only where it is used (#if).
VOXRAY_SWITCH(ADAPTIVE, 0, BUILD, "|adaptive")
// Packet rules the host must follow too, so it sets them (kernelSwitches() from the
// raycaster's facts) and the kernels only read them. mip: 4 x 2 packets a work-item marches
// together (mip_packet.cl),
// which sets the work-item grid's rows. iso: empty 2^3 voxel blocks a lane may pass per
// march iteration; the host makes the block bits only where this is above 0.
VOXRAY_SWITCH(MIP_HALVES, 1, BUILD, "")
VOXRAY_SWITCH(ISO_BLOCK_TRIES, 0, BUILD, "")
// dvr: each sample's opacity times a factor of its gradient magnitude (issue 35, VTK's gradient
// opacity; RenderParams::gradientOpacity), from the table behind the colour table
// (gradient_table.h, classification/gradient_opacity.cl). Set only with that field, so
// every other variant compiles as before (#if). Not with ADAPTIVE (its levels read the colour
// table alone); the light grid (shadows, ao) and the path tracer ignore the factor.
VOXRAY_SWITCH(GRADIENT_OPACITY, 0, BUILD, "|gopacity")
// dvr: colour and opacity from the 2D transfer function over (value, |gradient|) (issue 35,
// RenderParams::tf2d), a table behind the colour table (tf2d_table.h, classification/tf2d.cl),
// read with the gradient shading takes. The colour table then holds its largest opacity over
// gradient, which empty-space skipping and the first test of a sample read. Set only with that
// field (every other variant compiles as before); never with GRADIENT_OPACITY or ADAPTIVE; the
// light grid and the path tracer read the colour table (the largest over gradient).
VOXRAY_SWITCH(TF2D, 0, BUILD, "|tf2d")
// dvr: label-aware classification (issue 34, classification/labels.cl): each sample's colour
// mixed toward its nearest voxel's segment colour and its opacity times the label's factor
// (segment opacity, RenderParams::segmentMask), from the label map and the segment table
// (segment_table.h), two more kernel arguments. Set only where the raycaster holds a
// segmentation whose table changes something (Raycaster::setSegmentation), so every other
// variant compiles and renders as before (#if). Not with ADAPTIVE (its levels read the colour
// table alone); the light grid (shadows, ao) and the path tracer ignore the labels.
VOXRAY_SWITCH(LABELS, 0, BUILD, "|labels")
// dvr with LABELS: segments with their own 1D transfer function (issue 35, RenderParams::
// segmentTfs; classification/segment_tf.cl): a sample whose label has one is classified by it
// instead of the volume's table. One more kernel argument (the tables). Set only where a visible
// segment has such a table (engine/src/segment_tf.h), so every other variant compiles as before
// (#if); never with TF2D (its 2D table stays the volume's).
VOXRAY_SWITCH(SEGMENT_TF, 0, BUILD, "|segtf")
// dvr: a second volume fused into the same pass (issue 36, classification/overlay.cl): each
// sample also classifies the overlay at its patient point with the overlay's own table, and
// the two mix by summed extinction (march.cl, dvr_segment). Three more kernel arguments. Set
// only where the raycaster holds an overlay (Raycaster::setOverlay), so every other variant
// compiles and renders as before (#if). Not with ADAPTIVE (its levels read the base's table
// alone); the light grid (shadows, ao), the path tracer, iso and mip ignore the overlay.
VOXRAY_SWITCH(OVERLAY, 0, BUILD, "|overlay")
// dvr: segments shown as smooth surfaces (issue 34, Raycaster's surface pass,
// surface/surface_layer.cl): the march composites the pass's layer at its depth
// (classification/surfaces.cl), one more kernel argument. Set only where the raycaster holds a
// segmentation with a visible surface segment, so every other variant compiles as before (#if).
VOXRAY_SWITCH(SURFACES, 0, BUILD, "|surfaces")
// dvr: pre-integrated classification (issue 40, RenderParams::preintegrate;
// classification/preint.cl): each segment's colour and opacity from a 2D table over the
// previous sample's value and this one's (preint_table.h, behind the colour table), the
// opacity correction built in. A leap restarts from the sample before the first one it lands
// on, so skipping still changes no pixel. Set only where the raycaster is asked for it
// (KernelFacts::preintegrate), so every other variant compiles as before (#if); not with
// ADAPTIVE, TF2D, GRADIENT_OPACITY, LABELS, OVERLAY or SURFACES (they classify one sample);
// the light grid and the path tracer read the colour table.
VOXRAY_SWITCH(PREINT, 0, BUILD, "|preint")
// Image-space adaptive sampling (issue 40, RenderParams::adaptiveImage, adaptive/image_pass.cl):
// 0 the whole frame; 1 the lattice pass (every K-th pixel); 2 the refine pass (work-items that
// touch a refined block; one more kernel argument, the blocks' flags). Set by the raycaster per
// pass (engine/src/adaptive_image.cpp), never by kernelSwitches(), so every other variant
// compiles as before (#if).
VOXRAY_SWITCH(IMAGE_PASS, 0, BUILD, "|lattice|refine")

// The packets' tuning (VOXRAY_TUNING above), measured on CPUs (docs/bench/history). An
// experiment in a kernel directory (VOXRAY_KERNEL_DIR) tries another value with #undef and
// #define in its copy of the packet file.
// iso: samples loaded at once (iso_packet). Their gathers' misses are most of the kernel's
// time on a large volume; an 8-lane gather issues half the loads of a 16-lane one, so 8-lane
// packets keep four samples in flight (CT 512x512x400: three against two about -10 % kernel
// CPU; four against three -2 % in AVX-512 and in AVX2 builds, where session 9 under load
// could not tell); at 16 lanes three were no faster than two.
VOXRAY_TUNING(ISO_BATCH, 4, 2)
// dvr: samples per iteration (dvr_packet). 2 ran about 5 % faster than 1; 3 and 4 no faster
// than 2 (CThead, VTK's orbit).
VOXRAY_TUNING(DVR_BATCH, 2, 2)
// mip: a lane with no span left takes its next cell when at least 1 / MIP_REFILL of the
// active lanes wait, so that the packet's lanes keep sampling while one finishes a long span
// (before, every lane waited for the packet's longest span). Each refill scans every walked
// cell: refilling at every idle lane ran slower, at 1 / 4 no faster than at half (16 lanes).
// 8 lanes with two packets a work-item (MIP_HALVES): at 1 / 4 (2 of 8 lanes) CT kernel CPU
// -4 %, CThead -5 % (docs/bench, session 9).
VOXRAY_TUNING(MIP_REFILL, 4, 2)
// mip: samples a turn (mip_cells_brightest_firstN).
VOXRAY_TUNING(MIP_BATCH, 4, 4)
// mip: prefetch the voxel rows of turns MIP_PREFETCH_FROM .. MIP_PREFETCH_TO ahead (0: off).
VOXRAY_TUNING(MIP_PREFETCH, 1, 1)
VOXRAY_TUNING(MIP_PREFETCH_FROM, 1, 1)
VOXRAY_TUNING(MIP_PREFETCH_TO, 1, 1)

#ifdef VOXRAY_TUNING_UNSET
#undef VOXRAY_TUNING
#undef VOXRAY_TUNING_UNSET
#endif
