// TileBins: count, scan and scatter passes over storage buffers that grow with their use.
#include "render/tile_bins.h"

#include <algorithm>
#include <cstdint>

namespace ewa {

size_t TileBins::bin(const gl::Program& count, const gl::Program& scan, const gl::Program& scatter,
                     size_t items, size_t buckets, GLuint listBinding) {
  cursor_.reserve(GLsizeiptr(buckets * sizeof(uint32_t)), what_);
  offsets_.reserve(GLsizeiptr((buckets + 1) * sizeof(uint32_t)), what_);
  cursor_.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  offsets_.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  const uint32_t zero = 0;
  // This picture's buckets only: the buffer may be longer (reserve leaves room to grow).
  glClearNamedBufferSubData(cursor_.id(), GL_R32UI, 0, GLsizeiptr(buckets * sizeof(uint32_t)),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  gl::dispatchOver(count, items, 256);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  gl::dispatchOver(scan, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  uint32_t listed = 0;  // the lists' length sizes their buffer: one small read back
  offsets_.getSubData(GLintptr(buckets * sizeof(uint32_t)), sizeof listed, &listed);
  lists_.reserve(GLsizeiptr(size_t(listed) * sizeof(uint32_t)), what_);
  lists_.bindBase(GL_SHADER_STORAGE_BUFFER, listBinding);
  gl::dispatchOver(scatter, items, 256);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  return listed;
}

}  // namespace ewa
