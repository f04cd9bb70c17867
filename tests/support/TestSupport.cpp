#include "TestSupport.h"

#include <QtGlobal>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace px::test {

std::string sharedTestData(const std::string& relative) {
    return std::string(PX_SHARED_DIR) + "/testdata/" + relative;
}

Result<Tracer> makeTracer(const HeightField& field, WrapMode wrap, Technique technique, float scale,
                          const TraceParams* params) {
    TraceMaps maps;
    maps.height = &field;
    maps.wrap = wrap;
    return Tracer::create(maps, technique, params ? *params : info(technique).defaults, scale);
}

double bilinearHeight(const HeightField& field, WrapMode wrap, double u, double v) {
    const double X = u * field.width - 0.5, Y = v * field.height - 0.5;
    const double fx0 = std::floor(X), fy0 = std::floor(Y);
    const double fx = X - fx0, fy = Y - fy0;
    const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
    auto h = [&](int x, int y) {
        return static_cast<double>(
            field.at(wrapIndex(x, field.width, wrap), wrapIndex(y, field.height, wrap)));
    };
    return (h(x0, y0) * (1 - fx) + h(x0 + 1, y0) * fx) * (1 - fy) +
           (h(x0, y0 + 1) * (1 - fx) + h(x0 + 1, y0 + 1) * fx) * fy;
}

double denseMarchT(const HeightField& field, WrapMode wrap, double u0, double v0, double px,
                   double py, int samples) {
    auto f = [&](double t) {
        return bilinearHeight(field, wrap, u0 + px * t, v0 + py * t) - (1 - t);
    };
    if (f(0.0) >= 0)
        return 0.0;
    double prevT = 0.0;
    for (int k = 1; k <= samples; ++k) {
        const double t = static_cast<double>(k) / samples;
        const double ft = f(t);
        if (ft >= 0) {
            double lo = prevT, hi = t;
            for (int i = 0; i < 60; ++i) {
                const double mid = 0.5 * (lo + hi);
                (f(mid) >= 0 ? hi : lo) = mid;
            }
            return hi;
        }
        prevT = t;
    }
    return 1.0;
}

TestShard testShard() {
    TestShard shard;
    const char* value = std::getenv("PX_TEST_SHARD");
    if (!value)
        return shard;
    const std::string_view text(value);
    const std::size_t slash = text.find('/');
    const auto number = [&](std::string_view part, std::size_t& out) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), out);
        return error == std::errc() && end == part.data() + part.size() && !part.empty();
    };
    if (slash == std::string_view::npos || !number(text.substr(0, slash), shard.index) ||
        !number(text.substr(slash + 1), shard.count) || shard.index >= shard.count)
        qFatal("PX_TEST_SHARD=%s: expected i/n with 0 <= i < n", value);
    return shard;
}

} // namespace px::test
