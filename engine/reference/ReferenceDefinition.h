#pragma once
// What a CPU reference image was computed from, recorded in its EXR header so
// that `compare --reference` and `bench --reference` refuse a reference of
// another scene instead of reporting errors against it.
//
// The record is one digest per part of the scene the reference reads: the
// camera, the lights, the characters (meshes, materials, placement, pose),
// the diffusion profiles, the environment, and the settings it reads
// (ambient, energy_conservation, sss.enabled, sss.width_scale, sss.mix).
// The engine's own knobs (SSAO, taps, the mode, transmittance, which the
// reference leaves out, and how it approximates the environment: occlusion,
// diffuse, specular, SH bands, the extracted light) are not in it: a reference
// serves every setting of them.

#include "scene/Scene.h"

#include <string>
#include <vector>

namespace dermis::reference {

// The EXR attribute that holds the record (core/Image.h Image::attributes).
constexpr const char* kDefinitionAttribute = "dermis:reference_definition";
// Its samples per pixel (--spp): above 1 each pixel is a box filter over its
// area, where the engine shades the pixel's centre (docs/reference.md).
constexpr const char* kSamplesPerPixelAttribute = "dermis:reference_spp";

// "camera=HEX;lights=HEX;...": the record of `scene`.
std::string definitionRecord(const Scene& scene);

// The parts in which a recorded definition differs from `scene`'s, by name;
// empty when they agree. A part the record lacks counts as different.
std::vector<std::string> definitionMismatch(const std::string& record, const Scene& scene);

}  // namespace dermis::reference
