#include "plan/Aov.h"

namespace dermis {

bool aovIsUvLayout(Aov aov) { return aov == Aov::Stretch || aov == Aov::IrradianceTexture; }

}  // namespace dermis
