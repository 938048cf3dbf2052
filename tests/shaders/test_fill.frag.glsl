// Test shader: writes exactly known values (pixel centre, uniform colour) for read-back checks.
#include "test_common.glsl"

uniform vec4 uColor;

layout(location = 0) out vec4 fragColor;

void main() { fragColor = testValue(gl_FragCoord.xy, uColor); }
