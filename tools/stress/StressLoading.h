#pragma once
// How a stress case's scene reaches the renderer (StressCase::path): every
// scene is read by the scene loader, from its JSON text in memory or from a
// file with --set overrides; a hostile case's refusal is checked here.

#include "core/Result.h"
#include "stress/StressCases.h"

#include <string>

namespace dermis::stress {

// The scene to render: the loader's reading of the case's scene (Memory:
// from sceneToJson's text; Loader: from the file, with the overrides). An
// error is a generator bug (a Memory or Loader case must be a legal input) or
// a loader bug. For a Hostile case, the loader's answer as it is.
Result<Scene> loadCaseScene(const StressCase& c);

// For a Hostile case and the loader's result: empty when the loader refused
// the value with a message naming the file (or the override), the key and the
// range; otherwise what was wrong (accepted, or a vague message).
std::string refusalProblem(const StressCase& c, const Result<Scene>& loaded);

}  // namespace dermis::stress
