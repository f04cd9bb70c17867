#include "GoldenPolicy.h"

#include <cctype>
#include <filesystem>

namespace px::test {

std::string rendererKey(const std::string& glRenderer) {
    if (isLlvmpipe(glRenderer))
        return "llvmpipe";
    std::string key;
    for (char c : glRenderer) {
        if (std::isalnum(static_cast<unsigned char>(c)))
            key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!key.empty() && key.back() != '-')
            key += '-';
    }
    while (!key.empty() && key.back() == '-')
        key.pop_back();
    return key.empty() ? "unknown-renderer" : key;
}

GoldenRule goldenRule(const std::string& dir, const std::string& name,
                      const std::string& glRenderer, bool updating) {
    const std::string key = rendererKey(glRenderer);
    const std::string base = dir + "/" + name + ".png";
    if (key == "llvmpipe")
        return {base, kSameRendererTolerance, "llvmpipe: its own goldens, rounding noise only"};
    const std::string own = dir + "/" + key + "/" + name + ".png";
    if (updating || std::filesystem::exists(own))
        return {own, kSameRendererTolerance, key + ": its own goldens, rounding noise only"};
    return {base, kGpuTolerance,
            key + ": no goldens of its own (" + dir + "/" + key +
                "/), compared with llvmpipe's under the GPU tolerance"};
}

bool withinTolerance(const ImageDifference& d, const GoldenTolerance& t, int pixels) {
    return d.sameSize && d.meanAbs <= t.maxMeanSteps &&
           d.pixelsOver <= static_cast<int>(t.maxDifferingShare * pixels);
}

} // namespace px::test
