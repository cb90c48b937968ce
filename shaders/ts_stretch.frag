// Texture-space step 1: the stretch map (Chappuis 2011 §2.2.4 listing 2.1, Yang et al. 2012
// §II). RG16F: the world length of one UV unit along u and along v, in mm;
// the blur spaces its taps by sigma / stretch. Interpolated per-vertex
// derivatives, not dFdx per triangle (mesh/UvLayout.h says why); a
// degenerate triangle gives 0, which the blur treats as "do not blur here".
#include "Common.glsl"

in vec3 vDPduM;
in vec3 vDPdvM;

layout(location = 0) out vec2 oStretchMm;

void main() {
    vec2 stretchMm = vec2(length(vDPduM), length(vDPdvM)) * 1000.0;
    oStretchMm = sanitiseRange(stretchMm, 0.0, kHalfMax);
}
