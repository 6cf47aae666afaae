// Image-space adaptive sampling (issue 40; RenderParams::adaptiveImage, engine/src/
// adaptive_image.cpp): a frame in passes of the same raycast kernel.
//   IMAGE_PASS 1 (lattice): every K-th pixel in x and y, and the image's last column and row;
//     work coordinate (wx, wy) marches pixel (min(K wx, width - 1), min(K wy, height - 1)).
//   flags (image_flags.cl): a K x K block between four lattice pixels is refined where its
//     corners differ by THRESHOLD levels or more in a channel.
//   IMAGE_PASS 2 (refine): the whole frame's work-items, each marching only where its pixels
//     (a packet's 4 x rows, or one) touch a refined block: its rays and pixels are the plain
//     frame's, so refined pixels are the plain frame's to the bit.
//   fill (image_flags.cl): every other pixel bilinear between its block's corners.
// P->image_pass: K, the lattice's columns and rows (blocks + 1 each way), unused.
#ifndef VOXRAY_IMAGE_PASS_CL
#define VOXRAY_IMAGE_PASS_CL

#include "adaptive/image_blocks.cl"
#include "variant.cl"

// The lattice pass's pixel of work coordinate W along an axis of N pixels: N (outside the
// image, so the kernels' own bounds test drops it) past the lattice's C points.
// T: int, or intN for a packet's lanes.
#define LATTICE_PIXEL(T, w, k, c, n) select((T)(n), min((w) * (k), (T)((n)-1)), (w) < (c))

// Where the pass is the lattice, work coordinates (px, py) become its pixels in place.
#if IMAGE_PASS == 1
#define IMAGE_PASS_PIXEL(T, px, py)                                          \
  do {                                                                       \
    px = LATTICE_PIXEL(T, px, P->image_pass.x, P->image_pass.y, P->image.x); \
    py = LATTICE_PIXEL(T, py, P->image_pass.x, P->image_pass.z, P->image.y); \
  } while (0)
#else
#define IMAGE_PASS_PIXEL(T, px, py) \
  do {                              \
  } while (0)
#endif

// The refine pass's argument after the others: the blocks' flags (1: refined).
#if IMAGE_PASS == 2
#define IMAGE_PASS_PARAMS , __global const uchar* refine
#else
#define IMAGE_PASS_PARAMS
#endif

#endif
