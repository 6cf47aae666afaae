// Ray / box intersection (slab method), the seed's "bounding box", which is also the
// clip box. Components of the direction that are exactly zero never divide.
#ifndef VOXRAY_INTERSECT_CL
#define VOXRAY_INTERSECT_CL

// Returns the entry axis (0..2), -1 when the origin is inside the box, or -2 on a miss.
inline int intersect_box(float3 o, float3 d, float3 lo, float3 hi, float* t_enter, float* t_exit) {
  float t0 = -INFINITY, t1 = INFINITY;
  int axis = -1;
  float oa[3] = {o.x, o.y, o.z}, da[3] = {d.x, d.y, d.z};
  float loa[3] = {lo.x, lo.y, lo.z}, hia[3] = {hi.x, hi.y, hi.z};
  for (int a = 0; a < 3; ++a) {
    if (da[a] == 0.0f) {
      // A ray in a face's plane is inside: float rounding of its origin (FMA on GPUs) must
      // not decide it (engine/src/camera.cpp intersectBox uses the same margin).
      float margin = 1e-5f * (1.0f + fabs(loa[a]) + fabs(hia[a]));
      if (oa[a] < loa[a] - margin || oa[a] > hia[a] + margin) return -2;
      continue;
    }
    float inv = 1.0f / da[a];
    float ta = (loa[a] - oa[a]) * inv, tb = (hia[a] - oa[a]) * inv;
    if (ta > tb) {
      float s = ta;
      ta = tb;
      tb = s;
    }
    if (ta > t0) {
      t0 = ta;
      axis = a;
    }
    t1 = fmin(t1, tb);
  }
  if (t0 < 0.0f) {
    t0 = 0.0f;
    axis = -1;
  }
  *t_enter = t0;
  *t_exit = t1;
  return t1 >= t0 ? axis : -2;
}

#endif
