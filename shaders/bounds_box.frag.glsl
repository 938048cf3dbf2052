// The bounding box's fragments for the occlusion query: only whether they pass the stencil
// counts (colour writes are masked while it is drawn).
out vec4 outColor;

void main() { outColor = vec4(0.0); }
