// The blocks of image-space adaptive sampling (image_pass.cl): K x K pixels between four
// lattice pixels. ip: P->image_pass (K, lattice columns, lattice rows, unused).
#ifndef VOXRAY_IMAGE_BLOCKS_CL
#define VOXRAY_IMAGE_BLOCKS_CL

// The block (column or row) of pixel X: blocks span [K b, K b + K], the last one ending at
// the image's edge; an image one pixel wide has one block whose corners coincide.
inline int image_block(int x, int k, int blocks) { return min(x / k, blocks - 1); }

// Whether a pixel of [x0, x1] x [y0, y1] (inside the image) lies in a refined block.
inline bool image_refined(__global const uchar* flags, int4 ip, int x0, int y0, int x1, int y1) {
  int bw = max(ip.y - 1, 1), bh = max(ip.z - 1, 1);
  int bx1 = image_block(x1, ip.x, bw), by1 = image_block(y1, ip.x, bh);
  for (int by = image_block(y0, ip.x, bh); by <= by1; ++by)
    for (int bx = image_block(x0, ip.x, bw); bx <= bx1; ++bx)
      if (flags[by * bw + bx]) return true;
  return false;
}

#endif
