#include "core/Suggest.h"

#include <algorithm>

namespace dermis {

size_t editDistance(const std::string& a, const std::string& b) {
    // d[i][j]: edits between a's first i and b's first j characters.
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitute = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitute});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

std::string closestName(const std::string& given, const std::vector<std::string>& known) {
    const size_t limit = given.size() <= 4 ? 1 : given.size() <= 8 ? 2 : 3;
    std::string best;
    size_t bestDistance = limit + 1;
    for (const std::string& name : known) {
        const size_t distance = editDistance(given, name);
        if (distance < bestDistance && name != given) {
            best = name;
            bestDistance = distance;
        }
    }
    return best;
}

std::string didYouMean(const std::string& given, const std::vector<std::string>& known) {
    const std::string closest = closestName(given, known);
    return closest.empty() ? "" : " (did you mean '" + closest + "'?)";
}

}  // namespace dermis
