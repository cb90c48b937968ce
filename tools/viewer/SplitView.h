#pragma once
// Draws the frame into the window's scene area: one side, the A/B split with
// its divider, or the difference |A - B| in false colour. AOV outputs (linear
// floats) are mapped from a display range to [0, 1] first, sRGB-encoded where
// they are colours.

#include "core/Result.h"
#include "gl/GlObjects.h"

#include <glm/glm.hpp>

namespace dermis::viewer {

enum class ViewMode { Single, Split, Difference };

// A rectangle of the window in framebuffer pixels, origin bottom left (GL's).
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

enum class DisplayTransform {
    AsStored,    // the final image: already tone-mapped and sRGB-encoded
    Range,       // data (normals, depth, AO): (v - lo) / (hi - lo)
    RangeSrgb,   // linear colours: the range, then the sRGB encoding
};

struct DisplaySettings {
    ViewMode mode = ViewMode::Single;
    float dividerPx = 0.0f;  // split: x of the divider, from the scene area's left edge
    DisplayTransform transform = DisplayTransform::AsStored;
    glm::vec2 range{0.0f, 1.0f};
    float differenceScale = 10.0f;  // the difference is shown as max_rgb |A - B| times this
};

class SplitView {
public:
    static Result<SplitView> create();
    // `a` and `b` are the sides' output textures, each the scene area's size;
    // `b` is not read in the Single mode.
    void draw(const PixelRect& area, GLuint a, GLuint b, const DisplaySettings& settings) const;

private:
    gl::Program mProgram;
    gl::VertexArray mVertexArray;
};

}  // namespace dermis::viewer
