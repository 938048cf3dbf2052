// How far a kernel reaches: a line-for-line mirror of src/core/kernel_reach.cpp. REACH_FLOAT is
// the number type (float by default; the slab partition's compute pass defines it as double to
// place kernels in slabs exactly as the C++ does).
#ifndef REACH_FLOAT
#define REACH_FLOAT float
#endif

struct KernelReach {
  REACH_FLOAT cutoff;
  REACH_FLOAT depthCutoff;
  REACH_FLOAT maxSigma;
  REACH_FLOAT swanSpacing;
  bool swan;
  bool orthographic;
  REACH_FLOAT focalPixels;
  REACH_FLOAT pixelsPerUnit;
};

REACH_FLOAT worldPerPixel(KernelReach k, REACH_FLOAT depth) {
  return k.orthographic ? 1.0 / k.pixelsPerUnit : max(depth, 0.0) / k.focalPixels;
}

REACH_FLOAT reachStretch(KernelReach k, REACH_FLOAT depth) {
  return k.swan ? max(1.0, worldPerPixel(k, depth) / k.swanSpacing) : 1.0;
}

REACH_FLOAT worldReach(KernelReach k, REACH_FLOAT depth) {
  return sqrt(k.cutoff) * (k.maxSigma * reachStretch(k, depth) + worldPerPixel(k, depth));
}

REACH_FLOAT depthReach(KernelReach k, REACH_FLOAT depthVariance, REACH_FLOAT depth) {
  return sqrt(k.depthCutoff * depthVariance) * reachStretch(k, depth);
}
