// Shadow-map lookups with percentage-closer filtering (docs/shadows.md).
//
// The shadow pass stores linear depth in metres (R32F): along the light's axis
// for directional and spot lights (a 2-D map), the distance to the light for
// point lights (a cube map of six faces laid out 3x2 in one 2-D atlas,
// GpuLight.cubeShadow = 1). The same maps serve shadows and the transmittance
// thickness. A receiver is lit where its own light-space depth minus the bias
// is no further than the stored occluder depth. The bias is slope-scaled:
// constant + slope * texel footprint * tan(angle between N and L)
// (Papanikolaou 2013 §3).
//
// Filters (GpuLight.shadowFilter, DERMIS_SHADOW_FILTER_*):
//   PCF4X4: a 4x4 grid of taps, box-weighted (Chappuis 2011 §2.4);
//   POISSON: 16 Poisson-disc taps rotated per pixel by interleaved gradient noise
//      (Papanikolaou 2013 §3), trading banding for noise;
//   PCSS: percentage-closer soft shadows (Fernando 2005) for lights with a size
//      (GpuLight.size): a blocker search over the region the light's size
//      sets, the penumbra width the mean blocker depth implies, then PCF over a
//      disc of that width with DERMIS_PCSS_FILTER_SAMPLES fixed taps (no noise).
//      A delta light's exact shadow has a hard edge: PCSS gives it the sharpest
//      edge the map can, bilinear PCF (the four nearest texels' tests weighted
//      by the position between them; a ramp one texel wide). PCF4X4's ramp is
//      four texels wide: on the head scan its soft edges against the
//      reference's hard ones made the irradiance error 3.28% instead of 2.72%
//      (docs/shadows.md, "Delta lights").
// The wide kernels of POISSON on cube maps and of PCSS compare each tap with the
// receiver's plane where the tap's ray meets it, not with the receiver's own
// depth, so that a tilted receiver does not shadow itself across the kernel.
// A program compiles only the filters the frame's lights use
// (DERMIS_SHADOW_CODE, SharedConstants.glsl; every filter when not defined):
// CPU drivers such as llvmpipe run both sides of a branch under a mask, so
// the code of a filter no light uses cost as much as the filter that runs
// (the lighting pass of content/scenes/crowd8_mixed.json at 640x360: 98 ms
// with every filter, 34 ms with the hard edges alone; docs/shadows.md).
#ifndef DERMIS_SHADOWS_GLSL
#define DERMIS_SHADOWS_GLSL

#ifndef DERMIS_SHADOW_CODE
#define DERMIS_SHADOW_CODE DERMIS_SHADOW_CODE_EVERY_FILTER
#endif
#if DERMIS_SHADOW_CODE != DERMIS_SHADOW_CODE_HARD_EDGES && DERMIS_SHADOW_CODE != DERMIS_SHADOW_CODE_SOFT_EDGES && \
    DERMIS_SHADOW_CODE != DERMIS_SHADOW_CODE_EVERY_FILTER
#error "DERMIS_SHADOW_CODE must be one of DERMIS_SHADOW_CODE_* (SharedConstants.glsl)"
#endif

const vec2 kPoissonDisc[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

float interleavedGradientNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Point (i + 0.5) of `count` on the unit disc's golden-angle spiral (Vogel 1979):
// uniform in area, deterministic.
vec2 vogelDisc(int i, int count) {
    float r = sqrt((float(i) + 0.5) / float(count));
    float theta = float(i) * 2.39996323;
    return r * vec2(cos(theta), sin(theta));
}

bool isCubeShadow(GpuLight light) { return light.cubeShadow > 0.5; }

// Light-space linear depth (metres) of a world position: along the light's
// axis for 2-D maps, the distance to the light for cube maps.
float lightLinearDepth(GpuLight light, vec3 worldPositionM) {
    if (isCubeShadow(light)) return length(worldPositionM - light.positionM);
    return dot(worldPositionM - light.positionM, light.direction);
}

// Cube faces 0..5 (+x, -x, +y, -y, +z, -z): the axis each looks along and the
// directions of its atlas cell's u and v; face f is cell (f % 3, f / 3).
const vec3 kCubeAxis[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 kCubeU[6] = vec3[](vec3(0, 0, -1), vec3(0, 0, 1), vec3(1, 0, 0), vec3(1, 0, 0), vec3(1, 0, 0), vec3(-1, 0, 0));
const vec3 kCubeV[6] = vec3[](vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 0, -1), vec3(0, 0, 1), vec3(0, 1, 0), vec3(0, 1, 0));

int cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

// Clip position of the offset d (world, from the light) on face `face`: a 90-degree
// perspective between near and far (GpuLight.shadowNearM, shadowFarM).
vec4 cubeFaceClip(int face, vec3 d, float nearM, float farM) {
    float w = dot(d, kCubeAxis[face]);
    float z = (farM + nearM) / (farM - nearM) * w - 2.0 * farM * nearM / (farM - nearM);
    return vec4(dot(d, kCubeU[face]), dot(d, kCubeV[face]), z, w);
}

// Atlas coordinates of the direction d from the light, kept half a texel inside its face.
vec2 cubeAtlasUv(sampler2D atlas, vec3 d) {
    int face = cubeFace(d);
    vec2 uv = vec2(dot(d, kCubeU[face]), dot(d, kCubeV[face])) / dot(d, kCubeAxis[face]) * 0.5 + 0.5;
    float halfTexel = 0.5 / float(textureSize(atlas, 0).y / 2);
    uv = clamp(uv, vec2(halfTexel), vec2(1.0 - halfTexel));
    return (vec2(face % 3, face / 3) + uv) / vec2(3.0, 2.0);
}

// The stored occluder depth where the world position p projects; a large
// depth (unoccluded) outside a 2-D map.
float storedDepthM(sampler2D shadowMap, GpuLight light, vec3 p) {
    if (isCubeShadow(light)) return texture(shadowMap, cubeAtlasUv(shadowMap, p - light.positionM)).r;
    vec4 clip = light.shadowClipFromWorld * vec4(p, 1.0);
    if (clip.w <= kTiny) return 1e30;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1e30;
    return texture(shadowMap, uv).r;
}

// The four nearest texels' depth tests, bilinearly weighted (2-D maps).
float bilinearPcf(sampler2D shadowMap, vec2 uv, float testDepthM) {
    ivec2 size = textureSize(shadowMap, 0);
    vec2 st = uv * vec2(size) - 0.5;
    vec2 base = floor(st);
    vec2 w = st - base;
    float lit[4];
    for (int i = 0; i < 4; ++i) {
        ivec2 texel = clamp(ivec2(base) + ivec2(i & 1, i >> 1), ivec2(0), size - 1);
        lit[i] = testDepthM <= texelFetch(shadowMap, texel, 0).r ? 1.0 : 0.0;
    }
    return mix(mix(lit[0], lit[1], w.x), mix(lit[2], lit[3], w.x), w.y);
}

// A receiver's neighbourhood in the map: taps at offsets in texels move the
// receiver point by metresPerTexel along axisU and axisV, and each tap's
// receiver depth is where its ray from the light meets the receiver's plane.
struct ShadowFrame {
    vec3 positionM;
    vec3 N;
    vec3 axisU;
    vec3 axisV;
    float metresPerTexel;  // at the receiver
    float biasM;
};

// The receiver plane's light-space depth along the ray through q, minus the bias.
float planeTestDepthM(GpuLight light, ShadowFrame f, vec3 q) {
    float receiverDepthM = lightLinearDepth(light, f.positionM);
    if (light.shadowOrthographic > 0.5) {
        // Orthographic: the ray runs along the axis from q.
        float along = dot(f.N, light.direction);
        float deltaM = abs(along) > 0.05 ? dot(f.N, f.positionM - q) / along : 0.0;
        return receiverDepthM + deltaM - f.biasM;
    }
    vec3 fromLight = q - light.positionM;
    float toPlane = dot(f.N, fromLight);
    float scale = abs(toPlane) > 0.05 * length(fromLight) ? dot(f.N, f.positionM - light.positionM) / toPlane : 1.0;
    return lightLinearDepth(light, light.positionM + fromLight * scale) - f.biasM;
}

vec3 tapPosition(ShadowFrame f, vec2 offsetTexels) {
    return f.positionM + f.metresPerTexel * (offsetTexels.x * f.axisU + offsetTexels.y * f.axisV);
}

float tapLit(sampler2D shadowMap, GpuLight light, ShadowFrame f, vec2 offsetTexels) {
    vec3 q = tapPosition(f, offsetTexels);
    return planeTestDepthM(light, f, q) <= storedDepthM(shadowMap, light, q) ? 1.0 : 0.0;
}

// PCSS (Fernando 2005) with sizes in texels at the receiver. Directional:
// penumbra w = (d_receiver - d_blocker) tan(angular diameter), taken as
// 2 (d_r - d_b) tan(angular radius); spot and point (a sphere of radius R):
// w = 2 R (d_r - d_b) / d_b, at the receiver's depth. The blocker search
// returns the penumbra's half-width at the receiver (m), or -1 where it finds
// no blocker (the receiver sees the whole light).
float pcssPenumbraHalfWidthM(sampler2D shadowMap, GpuLight light, ShadowFrame f, float nearM) {
    float size = light.size;
    float receiverDepthM = lightLinearDepth(light, f.positionM);
    bool orthographic = light.shadowOrthographic > 0.5;
    // Blocker search: a blocker at depth z hides part of the light from the
    // receiver if it lies within the light's cone from the receiver, whose
    // radius at z, measured at the receiver's depth, is largest at the near plane.
    float searchM = orthographic ? size * (receiverDepthM - nearM)
                                 : size * (receiverDepthM - nearM) / nearM;
    float searchTexels = clamp(searchM / f.metresPerTexel, 1.0, float(DERMIS_PCSS_MAX_RADIUS_TEXELS));
    // Two searches: the near plane's region is far wider than the cone that
    // reaches the blockers, and a mean over it weights blockers the receiver
    // does not see the light past. The second search covers the penumbra the
    // first mean depth implies (still wider than the true one, since that mean
    // is nearer the light), and its mean sets the penumbra.
    float halfWidthM = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
        float blockerSumM = 0.0;
        float blockers = 0.0;
        for (int i = 0; i < DERMIS_PCSS_BLOCKER_SAMPLES; ++i) {
            vec3 q = tapPosition(f, searchTexels * vogelDisc(i, DERMIS_PCSS_BLOCKER_SAMPLES));
            float storedM = storedDepthM(shadowMap, light, q);
            if (storedM < planeTestDepthM(light, f, q)) {
                blockerSumM += storedM;
                blockers += 1.0;
            }
        }
        if (blockers == 0.0) return -1.0;
        float blockerDepthM = max(blockerSumM / blockers, 1e-4);
        halfWidthM = orthographic ? size * max(receiverDepthM - blockerDepthM, 0.0)
                                  : size * max(receiverDepthM - blockerDepthM, 0.0) / blockerDepthM;
        searchTexels = clamp(halfWidthM / f.metresPerTexel, 1.0, searchTexels);
    }
    return halfWidthM;
}

// The lit share of a disc of radius radiusTexels around the receiver:
// DERMIS_PCSS_FILTER_SAMPLES fixed taps (no noise).
float discPcf(sampler2D shadowMap, GpuLight light, ShadowFrame f, float radiusTexels) {
    float lit = 0.0;
    for (int i = 0; i < DERMIS_PCSS_FILTER_SAMPLES; ++i) {
        lit += tapLit(shadowMap, light, f, radiusTexels * vogelDisc(i, DERMIS_PCSS_FILTER_SAMPLES));
    }
    return lit / float(DERMIS_PCSS_FILTER_SAMPLES);
}

// The lit share of a disc of radius radiusM in the receiver's tangent plane
// (for light that travels along the surface, not across the light as a
// penumbra does): each tap is tested at its own light-space depth. A tap
// counts as shadowed only where the map's surface lies nearer the light than
// the tap by more than the tap's distance from the receiver: a surface that
// rises above the tangent plane at under 45 degrees (the receiver's own
// concave neighbourhood: an eye socket, the side of a nose) is the receiver
// itself, not a blocker; a blocker nearer than that (a contact shadow) is
// missed.
float surfaceTapLit(sampler2D shadowMap, GpuLight light, ShadowFrame f, float radiusM, int i) {
    vec2 offset = radiusM * vogelDisc(i, DERMIS_PCSS_FILTER_SAMPLES);
    vec3 q = f.positionM + offset.x * f.axisU + offset.y * f.axisV;
    return lightLinearDepth(light, q) - f.biasM - length(offset) <= storedDepthM(shadowMap, light, q) ? 1.0 : 0.0;
}

float surfaceDiscPcf(sampler2D shadowMap, GpuLight light, ShadowFrame f, float radiusM) {
    f.axisU = normalize(cross(f.N, abs(f.N.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    f.axisV = cross(f.N, f.axisU);
    // Every fourth tap first (an even spiral over the whole disc): where they
    // all agree, the disc is taken as wholly lit or wholly shadowed, and the
    // other three quarters are skipped, as most pixels lie far from an edge.
    float lit = 0.0;
    for (int i = 0; i < DERMIS_PCSS_FILTER_SAMPLES; i += 4) lit += surfaceTapLit(shadowMap, light, f, radiusM, i);
    const float firstTaps = float((DERMIS_PCSS_FILTER_SAMPLES + 3) / 4);
    if (lit == 0.0 || lit == firstTaps) return lit / firstTaps;
    for (int i = 0; i < DERMIS_PCSS_FILTER_SAMPLES; ++i) {
        if ((i & 3) != 0) lit += surfaceTapLit(shadowMap, light, f, radiusM, i);
    }
    return lit / float(DERMIS_PCSS_FILTER_SAMPLES);
}

float pcssVisibility(sampler2D shadowMap, GpuLight light, ShadowFrame f, float nearM) {
    float halfWidthM = pcssPenumbraHalfWidthM(shadowMap, light, f, nearM);
    if (halfWidthM < 0.0) return 1.0;
    // The smallest kernel is one texel: below that the map cannot resolve a penumbra.
    return discPcf(shadowMap, light, f, clamp(halfWidthM / f.metresPerTexel, 1.0, float(DERMIS_PCSS_MAX_RADIUS_TEXELS)));
}

// Where a receiver lies in a light's map: false where a 2-D map does not
// cover it (it is lit). uv: its map coordinates (2-D maps); f: its
// neighbourhood, with the texel footprint and the slope-scaled bias.
bool shadowReceiver(GpuLight light, vec3 worldPositionM, vec3 N, out vec2 uv, out ShadowFrame f) {
    bool cube = isCubeShadow(light);
    uv = vec2(0.0);
    if (!cube) {
        vec4 clip = light.shadowClipFromWorld * vec4(worldPositionM, 1.0);
        if (clip.w <= kTiny) return false;
        vec3 ndc = clip.xyz / clip.w;
        uv = ndc.xy * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return false;
    }

    float receiverDepthM = lightLinearDepth(light, worldPositionM);
    vec3 L = -light.direction;
    if (light.type != float(DERMIS_LIGHT_DIRECTIONAL)) L = safeNormalize(light.positionM - worldPositionM, N);
    float cosTheta = clamp(dot(N, L), 0.05, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    // Texel footprint in metres at the receiver: constant for orthographic,
    // growing with distance for perspective maps and cube faces.
    f.metresPerTexel = light.shadowTexelM * (light.shadowOrthographic > 0.5 ? 1.0 : max(receiverDepthM, 0.0));
    f.biasM = light.shadowBiasM + light.shadowSlopeBiasTexels * f.metresPerTexel * min(tanTheta, 10.0);
    f.positionM = worldPositionM;
    f.N = N;
    // Taps in texels around the receiver: along the map's axes (its clip
    // matrix's first two rows) for 2-D maps, across the direction to the light for cubes.
    if (cube) {
        vec3 d = normalize(worldPositionM - light.positionM);
        f.axisU = normalize(cross(d, abs(d.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
        f.axisV = cross(d, f.axisU);
    } else {
        mat4 m = light.shadowClipFromWorld;
        f.axisU = normalize(vec3(m[0][0], m[1][0], m[2][0]));
        f.axisV = normalize(vec3(m[0][1], m[1][1], m[2][1]));
    }
    return true;
}

// Fraction of the light that reaches worldPositionM, in [0,1].
float shadowVisibility(sampler2D shadowMap, GpuLight light, vec3 worldPositionM, vec3 N, vec2 pixel) {
    vec2 uv;
    ShadowFrame f;
    if (!shadowReceiver(light, worldPositionM, N, uv, f)) return 1.0;
    bool cube = isCubeShadow(light);
    float testDepthM = lightLinearDepth(light, worldPositionM) - f.biasM;
    int filterId = int(light.shadowFilter + 0.5);
    bool delta = !(light.size > 0.0);

#if DERMIS_SHADOW_CODE == DERMIS_SHADOW_CODE_HARD_EDGES
    return bilinearPcf(shadowMap, uv, testDepthM);  // every light: a 2-D map, delta, the PCSS filter
#else
    if (!cube && filterId == DERMIS_SHADOW_FILTER_PCSS && delta) return bilinearPcf(shadowMap, uv, testDepthM);
#if DERMIS_SHADOW_CODE == DERMIS_SHADOW_CODE_SOFT_EDGES
    return pcssVisibility(shadowMap, light, f, light.shadowNearM);  // every other light has a size
#else
    if (!cube && filterId == DERMIS_SHADOW_FILTER_PCF4X4) {
        vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
        float lit = 0.0;
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 4; ++x) {
                vec2 offset = (vec2(x, y) - 1.5) * texel;
                lit += testDepthM <= texture(shadowMap, uv + offset).r ? 1.0 : 0.0;
            }
        }
        return lit / 16.0;
    }
    if (!cube && filterId == DERMIS_SHADOW_FILTER_POISSON) {
        vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
        float angle = 6.2831853 * interleavedGradientNoise(pixel);
        mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
        float lit = 0.0;
        for (int i = 0; i < 16; ++i) {
            vec2 offset = rotation * kPoissonDisc[i] * 2.0 * texel;
            lit += testDepthM <= texture(shadowMap, uv + offset).r ? 1.0 : 0.0;
        }
        return lit / 16.0;
    }

    if (filterId == DERMIS_SHADOW_FILTER_PCSS && !delta) return pcssVisibility(shadowMap, light, f, light.shadowNearM);
    float lit = 0.0;
    if (filterId == DERMIS_SHADOW_FILTER_POISSON) {
        float angle = 6.2831853 * interleavedGradientNoise(pixel);
        mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
        for (int i = 0; i < 16; ++i) lit += tapLit(shadowMap, light, f, rotation * kPoissonDisc[i] * 2.0);
    } else {
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 4; ++x) lit += tapLit(shadowMap, light, f, vec2(x, y) - 1.5);
        }
    }
    return lit / 16.0;
#endif
#endif
}

#endif
