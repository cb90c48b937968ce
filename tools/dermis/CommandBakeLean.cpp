// dermis bake-lean: LEAN maps from a tangent-space normal map (engine/lean/LeanBake.h).
#include "Args.h"
#include "Commands.h"
#include "measure/Session.h"

#include "core/Image.h"
#include "core/Log.h"
#include "lean/LeanBake.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace dermis::cli {

using namespace measure;
namespace {

const char* const kHelp =
    "usage: dermis bake-lean NORMALMAP --out PREFIX [options]\n"
    "\n"
    "Bakes the two LEAN maps (Olano & Baker 2010) of a tangent-space normal map in any\n"
    "format OpenImageIO reads (+Y up, encoded as n * 0.5 + 0.5), with the full mip chain\n"
    "built by averaging the moments (exact), as 32-bit float OpenEXR mip-maps:\n"
    "  PREFIX_lean1.exr   (B.x, B.y, M.xx, M.yy)\n"
    "  PREFIX_lean2.exr   (M.xy, base slope variance m^2/2, 0, 1)\n"
    "with B = (n.x / n.z, n.y / n.z) the bump centre and M = (B.x^2, B.y^2, B.x B.y)\n"
    "its second moments. The renderer bakes the same maps itself when it loads a normal\n"
    "map; this command is for inspecting them and for other tools.\n"
    "\n"
    "options:\n"
    "  --out PREFIX        output prefix (required); directories are created\n"
    "  --roughness M       Beckmann roughness below the map's resolution, in [0, 1],\n"
    "                      stored as the base variance (default 0: the material decides)\n"
    "  --quiet             no progress messages (warnings stay)\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 on success, 1 when the image cannot be read or the maps cannot be\n"
    "written, 2 for bad command-line usage.\n";

Result<float> parseRoughness(const std::string& text) {
    size_t used = 0;
    float value = NAN;
    try {
        value = std::stof(text, &used);
    } catch (...) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !(value >= 0.0f && value <= 1.0f)) {
        return makeError("--roughness " + text, "expected a Beckmann roughness in [0, 1]");
    }
    return value;
}

}  // namespace

int runBakeLean(const std::vector<std::string>& rawArgs) {
    auto args = parseArgs(rawArgs, {"out", "roughness"}, {"quiet", "help"});
    if (!args.ok()) return usageError(args.error());
    if (args->flags.count("help")) {
        std::printf("%s", kHelp);
        return 0;
    }
    if (args->positional.size() != 1) return usageError(makeError("bake-lean", "expected exactly one NORMALMAP"));
    if (!args->has("out") || args->get("out", "").empty()) {
        return usageError(makeError("bake-lean", "--out PREFIX is required"));
    }
    auto roughness = parseRoughness(args->get("roughness", "0"));
    if (!roughness.ok()) return usageError(roughness.error());
    log::setQuiet(args->flags.count("quiet") > 0);

    const std::string input = args->positional[0];
    const std::string prefix = args->get("out", "");
    int sanitised = 0;
    auto normalMap = loadImage(input, ColourSpace::Linear, &sanitised);
    if (!normalMap.ok()) return failure(normalMap.error());
    // A normal map's NaN would bake into every mip level above it: refused, as an environment map's is.
    if (sanitised > 0)
        return failure(makeError(input, std::to_string(sanitised) + " texels are not finite (NaN or infinite); a normal map must be"));

    auto maps = bakeLeanMaps(*normalMap, *roughness);
    if (!maps.ok()) return failure(maps.error());
    if (const Status saved = saveLeanMaps(prefix, *maps); !saved.ok()) return failure(saved.error());
    log::info("wrote " + prefix + "_lean1.exr and " + prefix + "_lean2.exr (" + std::to_string(normalMap->width) + "x" +
              std::to_string(normalMap->height) + ", " + std::to_string(maps->levels()) + " mip levels)");
    return 0;
}

}  // namespace dermis::cli
