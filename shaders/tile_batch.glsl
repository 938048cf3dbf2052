// The compute EWA splatter's composites (tile_ewa.comp.glsl, tile_ewa_post.comp.glsl): a work
// group's batch of a bucket's splat records in shared memory, a batch splat's footprint at a
// pixel, and the group's early termination. Declared before it: kBatch, splats[], lists[],
// kIndexMask and uCutoff.
shared vec4 batch[4u * kBatch];
shared uint batchOpen[kBatch];  // each batch splat's list entry: its first/last-slab flags
shared uint unfinished;

// Whether any invocation of the group is `open`; every invocation of the group calls it.
bool groupOpen(bool open) {
  if (gl_LocalInvocationIndex == 0u) unfinished = 0u;
  barrier();
  if (open) atomicAdd(unfinished, 1u);
  barrier();
  return unfinished != 0u;
}

// Invocation `me` loads list entry k into the batch (none at or past `end`): the group loads
// each record once, and every pixel reads them all after the caller's barrier().
void loadBatchEntry(uint k, uint end, uint me) {
  if (k >= end) return;
  uint entry = lists[k];
  uint s = 4u * (entry & kIndexMask);
  for (uint i = 0u; i < 4u; ++i) batch[4u * me + i] = splats[s + i];
  batchOpen[me] = entry;
}

// Batch splat j's footprint at the pixel centred at `centre`: false past n and where the pixel
// lies outside the splat's box or cutoff; else its offset dx from the splat's centre and
// r = dx^T Q dx, as the splat fragments take them.
bool batchFootprint(uint j, uint n, vec2 centre, out vec2 dx, out float r) {
  r = 0.0;
  dx = vec2(0.0);
  if (j >= n) return false;
  vec4 box = batch[4u * j];
  dx = centre - box.xy;
  if (any(greaterThan(abs(dx), box.zw))) return false;
  vec4 q = batch[4u * j + 1u];
  r = q.x * dx.x * dx.x + 2.0 * q.y * dx.x * dx.y + q.z * dx.y * dx.y;
  return r <= uCutoff;
}
