#pragma once
// The radiance map a scene's environment names (Scene::environment.source):
// a built-in one (env/EnvironmentMap.h) or a lat-long file, loaded and checked
// (env/EnvironmentMap.h: loadEnvironmentMap). Not scaled by the intensity and
// not rotated: map space, as the file has it.

#include "core/Image.h"
#include "core/Result.h"
#include "scene/Scene.h"

namespace dermis {

Result<Image> loadEnvironmentSource(const Environment& environment);

}  // namespace dermis
