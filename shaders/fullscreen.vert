// One triangle that covers the viewport (vertices 0-2; uv in [0,1] across
// it), or two triangles per rectangle of uScreenRegions (vertices 3 on, six
// per rectangle: engine/render/FrameContext.h, drawRegions), so that one
// draw covers several disjoint parts of the frame. With
// FULLSCREEN_AT_FAR_PLANE the triangle lies on the far plane (depth 1): with
// GL_LEQUAL against a depth buffer it covers only what nothing was drawn on.
#define DERMIS_USE_SCREEN_REGIONS_BLOCK
#include "UniformBlocks.glsl"

out vec2 vUv;

const vec2 kQuadCorners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    if (gl_VertexID < 3) {
        vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
        vUv = corner;
#ifdef FULLSCREEN_AT_FAR_PLANE
        gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
#else
        gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
#endif
        return;
    }
    const int index = gl_VertexID - 3;
    const ivec4 region = uScreenRegions.regions[index / 6];
    const vec2 pixel = vec2(region.xy) + kQuadCorners[index % 6] * vec2(region.zw);
    vUv = pixel * uFrame.pixelSizeUv;
    gl_Position = vec4(vUv * 2.0 - 1.0, 0.0, 1.0);
}
