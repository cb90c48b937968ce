// TextureSpace.glsl: texture-space subsurface scattering (d'Eon & Luebke, as
// Chappuis 2011 chapter 2 and Yang et al. 2012 §II describe it). This header is its manual.
//
// WHAT IT DOES
//   The diffusion profile is a sum of Gaussians, R(r) = sum_i w_i G(v_i, r)
//   (Chappuis 2011 §2.1.4). Instead of blurring the lit image on screen, each
//   character's irradiance is rendered into its own UV layout and blurred
//   there, where the surface is flat and seen whole (Chappuis 2011 §2.2.1):
//     1. stretch     the world length of one UV unit along u and v, from the
//                    position derivatives (listing 2.1; per vertex, see
//                    mesh/UvLayout.h), to space the blur taps in mm.
//     2. irradiance  lights with PCF shadows (Shadows.glsl), the energy the
//                    specular lobe leaves (Chappuis 2011 §2.6), ambient (times the
//                    SSAO where the texel is on screen), times albedo^mix
//                    (pre-scatter, §2.2.4); in alpha the thickness towards
//                    the TSM light as exp(-c d) (§2.5, listing 2.7).
//     3. dilate      empty texels next to a chart take the nearest chart
//                    texel, so taps past a chart's edge read plausible light,
//                    never black.
//     4. blurs       texture i is texture i-1 blurred by v_i - v_(i-1), U
//                    then V, sigma turned into texels by the stretch map
//                    (§2.2.4, listing 2.2): every texel within 3 sigma,
//                    weighted by the Gaussian integrated over it, up to 16
//                    texels; beyond, N taps spaced by sigma (ts_blur.frag
//                    says why). Gaussian 0 is the irradiance itself unless
//                    it spans texels (plan/TsPlan.h). Alpha is blurred
//                    along, so the thickness is smooth (§2.5).
//     5. gather      in screen space, for the character's pixels (the
//                    surface the G-buffer kept, by its stored view depth):
//                    sum_i w_i T_i(uv) / sum_i w_i, each T_i giving way to
//                    T_0 (the narrowest, "local" light) near a chart border,
//                    its mass beyond the border taking the light across it
//                    (at a seam, T_i on the chart beyond: mesh/UvLayout.h;
//                    ts_gather.frag), plus the TSM terms; the
//                    composite then applies albedo^(1-mix), the outgoing
//                    energy and the specular, as in screen-space mode.
//
// TRANSLUCENT SHADOW MAP (Chappuis 2011 §2.5)
//   Rendered from the TSM light, it keeps, per texel, the depth and the UV of
//   the surface nearest the light (and its normal). For a point C on the far
//   side of a thin region, A = TSM(C) is where the light went in, and the
//   light leaving C through Gaussian i is
//     w_i exp(-d^2 / (2 v_i)) T_i(uv_A)
//   since G(v, sqrt(r^2 + d^2)) = exp(-d^2 / 2v) G(v, r) for
//   G(v, r) = exp(-r^2 / 2v) / (2 pi v) (listing 2.11; the text's
//   e^(-d^2/v) writes the Gaussian another way). d is read from the alpha of
//   texture i-1 at C (the text: "the alpha channel of convolved irradiance
//   texture i - 1"), and the term fades to zero as uv_A approaches uv_C,
//   where the ordinary blur already carries that light: the fix for double
//   contribution, weight clamp(|uv_C - uv_A| mm / (6 sigma_i), 0, 1). As in
//   listing 2.11 only the three widest Gaussians get a TSM term (uTs.tsmFirstGaussian
//   is the first).
//
// INTEGRATION (passes/TextureSpacePasses.cpp does this)
//   Every pass binds TextureSpaceBlock (UniformBlocks.glsl, per character)
//   and the character's ObjectBlock; the mesh passes draw its TsMesh
//   (render/TsMeshes.h, attributes 0-6).

#ifndef DERMIS_TEXTURE_SPACE_GLSL
#define DERMIS_TEXTURE_SPACE_GLSL

// Thickness given to points that face the TSM light or see no thin region
// behind them: large enough that exp(-d^2 / 2v) vanishes for every skin
// Gaussian (listing 2.7 sets "a large distance" the same way).
const float kTsFrontThicknessMm = 50.0;
// Nearer than this behind the TSM surface is the surface itself (listing 2.7
// sets such points to the large distance to remove shadow-map artifacts);
// screen space uses the same rule.
const float kTsMinThicknessMm = DERMIS_SELF_THICKNESS_MM;
// Covered texels keep alpha above 0; 0 marks an empty texel.
const float kTsMinAlpha = 1e-4;

// Depth in the TSM: along the axis for directional lights, the distance to the
// light for spot lights (plan/TsPlan.h).
float tsmDepthM(vec3 worldPositionM) {
    vec3 d = worldPositionM - uTs.tsmOriginM;
    return uTs.tsmAlongAxis > 0.5 ? dot(d, uTs.tsmAxis) : length(d);
}

// Unit vector from a point towards the TSM light.
vec3 tsmToLight(vec3 worldPositionM) {
    return uTs.tsmAlongAxis > 0.5 ? -uTs.tsmAxis
                                 : safeNormalize(uTs.tsmOriginM - worldPositionM, -uTs.tsmAxis);
}

// The TSM texel over a world position: x depth (m), yz uv of the light-facing
// surface, w packed normal; w = 0 where the character does not cover the
// map. Nearest texel: interpolating UVs across a silhouette would invent
// points.
vec4 tsmTap(sampler2D tsm, vec3 worldPositionM) {
    vec4 clip = uTs.tsmClipFromWorld * vec4(worldPositionM, 1.0);
    if (clip.w <= kTiny) return vec4(0.0);
    vec2 st = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(st, vec2(0.0))) || any(greaterThanEqual(st, vec2(1.0)))) return vec4(0.0);
    ivec2 size = textureSize(tsm, 0);
    return texelFetch(tsm, clamp(ivec2(st * vec2(size)), ivec2(0), size - 1), 0);
}

// A unit normal packed into one float as two 8-bit octahedral components
// (exact in fp32), and back.
float packTsmNormal(vec3 n) {
    vec2 e = clamp(encodeNormal(n) * 0.5 + 0.5, 0.0, 1.0);
    vec2 q = floor(e * 255.0 + 0.5);
    return q.x * 256.0 + q.y + 1.0;  // + 1: 0 stays "empty"
}
vec3 unpackTsmNormal(float packedNormal) {
    float v = max(packedNormal - 1.0, 0.0);
    vec2 q = vec2(floor(v / 256.0), mod(v, 256.0));
    return decodeNormal(q / 255.0 * 2.0 - 1.0);
}

// Thickness (mm) through the character towards the TSM light, corrected as
// listing 2.7 does: towards the most direct path (cos q) where the surface
// seen by the light faces the opposite way.
float tsmThicknessMm(sampler2D tsm, vec3 worldPositionM, vec3 N) {
    vec3 L = tsmToLight(worldPositionM);
    float nDotL = dot(N, L);
    vec4 tap = tsmTap(tsm, worldPositionM);
    if (nDotL > 0.0 || tap.w <= 0.0) return kTsFrontThicknessMm;
    float thicknessMm = (tsmDepthM(worldPositionM) - tap.x) * 1000.0;
    if (thicknessMm < kTsMinThicknessMm) return kTsFrontThicknessMm;
    float backFacing = clamp(-dot(unpackTsmNormal(tap.w), N), 0.0, 1.0);
    float corrected = clamp(-nDotL, 0.0, 1.0) * thicknessMm;
    return min(mix(thicknessMm, corrected, backFacing), kTsFrontThicknessMm);
}

float encodeThickness(float thicknessMm) { return max(exp(-uTs.tsmPerMm * thicknessMm), kTsMinAlpha); }
float decodeThicknessMm(float alpha) { return -log(max(alpha, kTsMinAlpha)) / max(uTs.tsmPerMm, kTiny); }

#endif
