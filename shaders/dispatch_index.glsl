// The invocation's number on gl::dispatchOver's grid (src/gl/program.h): rows of 65535 groups
// of `groupWidth` invocations.
uint dispatchIndex(uint groupWidth) {
  return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * groupWidth;
}
