#include "plan/ScreenRegions.h"

#include <algorithm>

namespace dermis {
namespace {

bool empty(const glm::ivec4& r) { return r.z <= 0 || r.w <= 0; }

long long area(const glm::ivec4& r) { return empty(r) ? 0 : (long long)r.z * r.w; }

// a minus b: up to four rectangles (below, above, left, right of b).
void subtract(const glm::ivec4& a, const glm::ivec4& b, std::vector<glm::ivec4>& out) {
    const int ax1 = a.x + a.z, ay1 = a.y + a.w, bx1 = b.x + b.z, by1 = b.y + b.w;
    if (b.x >= ax1 || bx1 <= a.x || b.y >= ay1 || by1 <= a.y) {
        out.push_back(a);
        return;
    }
    const int y0 = std::max(a.y, b.y), y1 = std::min(ay1, by1);
    if (b.y > a.y) out.emplace_back(a.x, a.y, a.z, b.y - a.y);
    if (by1 < ay1) out.emplace_back(a.x, by1, a.z, ay1 - by1);
    if (b.x > a.x) out.emplace_back(a.x, y0, b.x - a.x, y1 - y0);
    if (bx1 < ax1) out.emplace_back(bx1, y0, ax1 - bx1, y1 - y0);
}

}  // namespace

std::vector<glm::ivec4> disjointCover(const std::vector<glm::ivec4>& rects) {
    std::vector<glm::ivec4> cover;
    glm::ivec2 lo(0), hi(0);
    bool any = false;
    for (const glm::ivec4& rect : rects) {
        if (empty(rect)) continue;
        lo = any ? glm::min(lo, glm::ivec2(rect)) : glm::ivec2(rect);
        hi = any ? glm::max(hi, glm::ivec2(rect) + glm::ivec2(rect.z, rect.w)) : glm::ivec2(rect) + glm::ivec2(rect.z, rect.w);
        any = true;
        std::vector<glm::ivec4> pieces{rect}, next;
        for (const glm::ivec4& existing : cover) {
            next.clear();
            for (const glm::ivec4& piece : pieces) subtract(piece, existing, next);
            pieces.swap(next);
        }
        cover.insert(cover.end(), pieces.begin(), pieces.end());
    }
    if (!any) return cover;
    const glm::ivec4 box(lo, hi - lo);
    long long covered = 0;
    for (const glm::ivec4& r : cover) covered += area(r);
    if (cover.size() > kMaxScreenRegions || double(covered) > kRegionAreaShareForOneBox * double(area(box))) return {box};
    return cover;
}

}  // namespace dermis
