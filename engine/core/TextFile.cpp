#include "core/TextFile.h"

#include "core/OutputFiles.h"

namespace dermis {

Status writeTextFileAtomically(const std::string& path, const std::string& text) {
    OutputFiles out;
    if (Status staged = out.stageText(path, text); !staged) return staged;
    return out.commit();
}

}  // namespace dermis
