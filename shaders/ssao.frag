// Screen-space ambient occlusion (docs/screen-space.md, step 3; Papanikolaou 2013 §3.2): a
// normal-oriented hemisphere of sample points around each pixel's view-space
// position, rotated per pixel, with a radius and a sample count per object.
//
// INTEGRATION
//   Program: fullscreen.vert + ssao.frag (Programs::ssao), driven by
//   engine/passes/SsaoPass.cpp (addSsaoPasses), which also runs the
//   depth-aware blur ssao_blur.frag. Draw one fullscreen triangle into an R8
//   target of the G-buffer's size. Inputs:
//     unit 0  uDepth           G-buffer D24S8 depth (sampled as depth)
//     unit 1  uNormalMaterial  G-buffer RGBA16F, xy = octahedral VIEW-space normal
//     unit 2  uAlbedo          G-buffer RGBA16F, a = object id / 255 (0 = background)
//     FrameBlock       viewFromClip, clipFromView, viewportPx, pixelSizeUv, ssaoStrength
//     CharactersBlock  characters[id].ssaoRadiusM, ssaoSamples
//     SsaoBlock        (DERMIS_BINDING_PASS) fallbacks and biases, see below
//   Output: AO in [0, 1], 1 = unoccluded. It multiplies only the ambient /
//   environment term of the lighting, never direct light.
//
// CONFIGURATION (scene file -> where it arrives -> default)
//   settings.ssao.enabled     the pass is skipped by graph predicate    true
//   settings.ssao.strength    uFrame.ssaoStrength, in [0, 1]:             1
//                             AO = 1 - strength * occlusion
//   settings.ssao.radius_m    hemisphere radius in metres (world and    0.02
//                             view space share units); per character
//                             "ssao": {"radius_m"} overrides it
//                             (CharactersBlock params.y; 0 there means
//                             uSsao.radiusM, the scene's value)
//   settings.ssao.samples     sample points per pixel, 8..128; per      16
//                             character "ssao": {"samples"} overrides
//                             (params.z; 0 means uSsao.samples)
//   uSsao.biasFraction        bias as a fraction of the radius: an      0.02
//                             occluder must lie this far in front of the
//                             sample point and above the tangent plane
//   uSsao.fadeEndRadii        range check: an occluder's weight fades   2
//                             from 1 at distance `radius` from the pixel
//                             to 0 at `fadeEndRadii x radius`
//   Papanikolaou 2013 finds 32..64 samples the best accuracy per time; fewer are
//   noisy before the blur, more than 128 cost much and change little.
//
// METHOD
//   Sample directions are generated here, deterministically, for any count
//   n: point i of a Fibonacci spiral on the unit disc, r = sqrt((i+0.5)/n),
//   phi = i x golden angle, lifted onto the hemisphere (z = sqrt(1 - r^2)).
//   That is a cosine-weighted distribution, as in the visibility integral of
//   Papanikolaou 2013 §3.2 (1/pi integral of V (w.n) dw). Sample i's distance is
//   radius x mix(0.1, 1, t^2), t a golden-ratio sequence in i with a
//   per-pixel offset, so near occluders get more samples. A sample counts
//   when its point is inside geometry, not when anything lies along its
//   direction, so (as with Papanikolaou 2013's kernel) the result is lighter than
//   ray-traced AO of the same radius, most where the occluder is nearly
//   a radius away.
//   The hemisphere is rotated about the normal by interleaved gradient noise
//   (Jimenez 2014) instead of Papanikolaou 2013's 64x64 noise texture, and the
//   tangent frame is built by Gram-Schmidt as in Papanikolaou 2013 §3.2.2.
//   Each sample point S is projected to a texel whose visible surface point
//   Q is reconstructed from the depth buffer. The sample counts as occluded
//   (Papanikolaou 2013 §3.2.2 step 2.5.4, with the bias of step 2.5.5) when
//     - Q is in front of S by more than the bias, and
//     - Q lies above the pixel's tangent plane by more than the bias: on a
//       flat surface Q is the surface itself and never occludes, however
//       the texel snapping shifts its depth at grazing angles;
//   and its weight falls with |Q - P| (the range check), so a foreground
//   object far in front does not draw a dark halo on what is behind it.
//   Samples that leave the screen, go behind the camera or land on the
//   background count as unoccluded.
//
// Cost per pixel: per sample two 4x4 matrix products and one depth fetch.
//
// Every output is finite: background, object id 0, a zero/NaN radius or zero
// strength give 1; normals decode through safeNormalize.
#define DERMIS_USE_SSAO_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uNormalMaterial;
layout(binding = 2) uniform sampler2D uAlbedo;

layout(location = 0) out vec4 oAo;

const int kMaxSamples = DERMIS_MAX_SSAO_SAMPLES;
const float kMaxRadiusM = 1.0e3;
const float kGoldenAngle = 2.39996323;  // pi (3 - sqrt 5)
const float kGoldenFraction = 0.61803399;
const float kNearestSampleFraction = 0.1;

// Jimenez 2014, "Next generation post processing in Call of Duty: AW".
float interleavedGradientNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

vec3 viewPositionAt(ivec2 texel, float depth) {
    vec2 uv = (vec2(texel) + 0.5) * uFrame.pixelSizeUv;
    return viewPositionFromDepth(uv, depth, uFrame.viewFromClip);
}

// Direction i of n, cosine-weighted over the +z hemisphere.
vec3 hemisphereDirection(int i, int n) {
    float u = (float(i) + 0.5) / float(n);
    float r = sqrt(u);
    float phi = float(i) * kGoldenAngle;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u, 0.0)));
}

float ambientOcclusion(ivec2 pixel) {
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (!(depth < 1.0)) return 1.0;  // background (or NaN)
    int objectId = int(texelFetch(uAlbedo, pixel, 0).a * 255.0 + 0.5);
    if (objectId <= 0 || objectId > DERMIS_MAX_CHARACTERS) return 1.0;

    CharacterParams character = uCharacters.characters[objectId];
    float radiusM = character.ssaoRadiusM > 0.0 ? character.ssaoRadiusM : uSsao.radiusM;
    float sampleCount = character.ssaoSamples >= 1.0 ? character.ssaoSamples : uSsao.samples;
    float strength = clamp(uFrame.ssaoStrength, 0.0, 1.0);  // NaN clamps to an end; both are finite
    if (!(radiusM > 0.0) || !(sampleCount >= 1.0) || !(strength > 0.0)) return 1.0;
    radiusM = min(radiusM, kMaxRadiusM);
    int samples = int(min(sampleCount, float(kMaxSamples)));
    float biasM = max(uSsao.biasFraction, 0.0) * radiusM;
    float fadeEndM = max(uSsao.fadeEndRadii, 1.0 + 1e-3) * radiusM;

    vec3 P = viewPositionAt(pixel, depth);
    vec3 N = decodeNormal(texelFetch(uNormalMaterial, pixel, 0).xy);

    // Tangent frame rotated about N by the noise angle (Papanikolaou 2013 §3.2.2, getRotatedTBN).
    float angle = 2.0 * kPi * interleavedGradientNoise(gl_FragCoord.xy);
    vec3 randomVector = vec3(cos(angle), sin(angle), 0.0);
    vec3 fallback = abs(N.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 T = safeNormalize(randomVector - N * dot(N, randomVector), safeNormalize(fallback - N * dot(N, fallback), fallback));
    vec3 B = cross(N, T);
    float distanceOffset = hashToUnit(uvec2(pixel));

    float occlusion = 0.0;
    for (int i = 0; i < samples; ++i) {
        vec3 d = hemisphereDirection(i, samples);
        float t = fract(float(i) * kGoldenFraction + distanceOffset);
        float lengthM = radiusM * mix(kNearestSampleFraction, 1.0, t * t);
        vec3 S = P + lengthM * (T * d.x + B * d.y + N * d.z);

        vec4 clip = uFrame.clipFromView * vec4(S, 1.0);
        if (!(clip.w > kTiny)) continue;  // behind the camera
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (!(all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0))))) continue;
        ivec2 texel = ivec2(uv * uFrame.viewportPx);
        float occluderDepth = texelFetch(uDepth, texel, 0).r;
        if (!(occluderDepth < 1.0)) continue;  // background never occludes
        vec3 Q = viewPositionAt(texel, occluderDepth);

        // View space looks down -z: larger z is nearer the camera.
        if (Q.z < S.z + biasM) continue;
        vec3 toOccluder = Q - P;
        if (dot(toOccluder, N) <= biasM) continue;
        occlusion += 1.0 - smoothstep(radiusM, fadeEndM, length(toOccluder));
    }
    float ao = 1.0 - strength * occlusion / float(samples);
    return sanitiseRange(ao, 0.0, 1.0, 1.0);
}

void main() {
    oAo = vec4(ambientOcclusion(ivec2(gl_FragCoord.xy)));
}
