// The pre-integrated skin technique's constants (Penner & Borshukov 2011),
// shared by its C++ (engine/sss/PreintegratedTable.h, PreintegratedShadow.h)
// and its GLSL (PreintegratedSkin.glsl). Only #defines, like SharedConstants.glsl.
#ifndef DERMIS_PREINTEGRATED_CONSTANTS_GLSL
#define DERMIS_PREINTEGRATED_CONSTANTS_GLSL

// The table's size and its curvature axis, y = sqrt(curvature / max): a sphere of radius
// 1 mm at y = 1, a flat surface at y = 0.
#define DERMIS_PREINTEGRATED_COSINES 64
#define DERMIS_PREINTEGRATED_CURVATURES 64
#define DERMIS_PREINTEGRATED_MAX_CURVATURE_PER_MM 1.0
// Its shadows (engine/sss/PreintegratedShadow.h): per slot, this many rows of
// DERMIS_PREINTEGRATED_COSINES texels above the slot's falloff rows, x: the shadow
// map's coverage of a disc around the receiver, y = q / (1 + q), q the light's
// penumbra half-width over twice the slot's sigma (the widest standard deviation of
// the Gaussians that carry 10% of a channel); the disc's radius is
// DERMIS_PREINTEGRATED_SHADOW_STDDEVS sigma sqrt(1 + q^2).
#define DERMIS_PREINTEGRATED_SHADOW_ROWS 16
#define DERMIS_PREINTEGRATED_SHADOW_STDDEVS 2.0
// Below this sigma on screen (pixels) the scattered shadow cannot show, and the
// lighting pass takes the light's plain shadow lookup, which costs less.
#define DERMIS_PREINTEGRATED_SHADOW_MIN_SIGMA_PX 0.5
// A slot's whole table: the falloff's rows, then the shadow's.
#define DERMIS_PREINTEGRATED_SLOT_ROWS (DERMIS_PREINTEGRATED_CURVATURES + DERMIS_PREINTEGRATED_SHADOW_ROWS)

#endif
