#pragma once
// Writing a whole text file so that a failure never leaves a partial one: the
// text goes to a temporary file beside the target, which is then renamed
// (core/OutputFiles.h, where a command with several outputs stages them all).

#include "core/Result.h"

#include <string>

namespace dermis {

// Creates missing parent directories. Errors name the path.
Status writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace dermis
