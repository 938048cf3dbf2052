// The screen tiles a footprint's box reaches, for the compute tile splatters' binning passes.

// The first and last tile (`tile` pixels a side) holding pixels whose centres lie in `box`
// (centre x, centre y, half width, half height in pixels; y up, pixel centres at +0.5) inside
// a `viewport`-sized picture; false where the box misses the picture.
bool boxTiles(vec4 box, ivec2 viewport, int tile, out ivec2 t0, out ivec2 t1) {
  ivec2 lo = ivec2(ceil(box.xy - box.zw - 0.5));
  ivec2 hi = ivec2(floor(box.xy + box.zw - 0.5));
  if (any(greaterThan(lo, viewport - 1)) || any(lessThan(hi, ivec2(0)))) return false;
  t0 = clamp(lo, ivec2(0), viewport - 1) / tile;
  t1 = clamp(hi, ivec2(0), viewport - 1) / tile;
  return true;
}
