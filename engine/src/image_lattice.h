#pragma once
// The lattice of image-space adaptive sampling (adaptive_image.h), without OpenCL: what the
// passes and the tests agree on.
namespace voxray {

// The lattice of a WIDTH x HEIGHT frame at spacing K: its columns and rows (every K-th pixel
// and the last one), and the blocks between them (at least one each way).
struct ImageLattice {
  int k = 4;
  int cols = 1, rows = 1;
  int blocksX() const { return cols > 1 ? cols - 1 : 1; }
  int blocksY() const { return rows > 1 ? rows - 1 : 1; }
};
ImageLattice imageLattice(int width, int height, int k);

}  // namespace voxray
