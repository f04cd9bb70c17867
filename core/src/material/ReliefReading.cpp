#include "parallax/material/ReliefReading.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace px {

namespace {

// Below this a slope correlation says nothing (noise, or another set's normal map).
constexpr double kTellable = 0.2;

struct Pearson {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
    void add(double a, double b) {
        sa += a;
        sb += b;
        saa += a * a;
        sbb += b * b;
        sab += a * b;
        n += 1;
    }
    double r() const {
        if (n < 2)
            return 0.0;
        const double cov = sab / n - (sa / n) * (sb / n);
        const double va = saa / n - (sa / n) * (sa / n), vb = sbb / n - (sb / n) * (sb / n);
        return va > 1e-12 && vb > 1e-12 ? cov / std::sqrt(va * vb) : 0.0;
    }
};

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

const char* readingName(bool depth) {
    return depth ? "a depth map (white = deep)" : "a height map (white = high)";
}

} // namespace

Result<ReliefReading> readRelief(const HeightField& file, const Image& normals, WrapMode wrap,
                                 bool depthByName, const std::string& normalSource) {
    if (normals.empty() || normals.channels < 2)
        return fileError(normalSource, "a normal map needs at least red and green channels");
    if (file.empty())
        return Error{"the height map is empty"};
    // Central differences of the height file at each normal texel's centre (nearest height texel).
    Pearson u, v;
    for (int y = 0; y < normals.height; ++y) {
        const int hy = static_cast<int>((y + 0.5) * file.height / normals.height);
        const int y0 = wrapIndex(hy - 1, file.height, wrap),
                  y1 = wrapIndex(hy + 1, file.height, wrap);
        for (int x = 0; x < normals.width; ++x) {
            const int hx = static_cast<int>((x + 0.5) * file.width / normals.width);
            const int x0 = wrapIndex(hx - 1, file.width, wrap),
                      x1 = wrapIndex(hx + 1, file.width, wrap);
            u.add(normals.at(x, y, 0), -(double(file.at(x1, hy)) - file.at(x0, hy)));
            v.add(normals.at(x, y, 1), double(file.at(hx, y1)) - file.at(hx, y0));
        }
    }
    ReliefReading reading;
    reading.slopeU = u.r();
    reading.slopeV = v.r();
    if (std::abs(reading.slopeU) < kTellable && std::abs(reading.slopeV) < kTellable) {
        reading = reliefByName(depthByName, "");
        reading.slopeU = u.r();
        reading.slopeV = v.r();
        char text[256];
        std::snprintf(text, sizeof text,
                      "The normal map's slopes do not follow the height map's (r = %.2f across, "
                      "%.2f down): is it this set's normal map? The height file is read as %s "
                      "by its name; flip it if the relief looks inverted.",
                      reading.slopeU, reading.slopeV, readingName(depthByName));
        reading.summary = text;
        return reading;
    }
    // Depth flips both slopes; DirectX green flips the second. Red alone has one convention, so
    // it decides height or depth whenever it can; green then decides the convention.
    struct Candidate {
        bool depth;
        NormalGreen green;
        double score;
    };
    const double su = reading.slopeU, sv = reading.slopeV;
    const std::array<Candidate, 4> candidates{{
        {false, NormalGreen::OpenGL, (su + sv) / 2},
        {false, NormalGreen::DirectX, (su - sv) / 2},
        {true, NormalGreen::OpenGL, (-su - sv) / 2},
        {true, NormalGreen::DirectX, (-su + sv) / 2},
    }};
    Candidate best = candidates[0];
    for (const Candidate& c : candidates) {
        if (c.score > best.score)
            best = c;
    }
    reading.depth = best.depth;
    reading.green = best.green;
    reading.score = best.score;
    reading.fromData = true;
    char text[320];
    std::snprintf(text, sizeof text,
                  "Told by the normal map %s: the height file is %s and the normal map's green "
                  "is %s (slopes agree with r = %.2f across, %.2f down).",
                  fileName(normalSource).c_str(), readingName(best.depth),
                  best.green == NormalGreen::OpenGL ? "OpenGL (Y+)" : "DirectX (Y-)",
                  best.depth ? -su : su,
                  (best.depth != (best.green == NormalGreen::DirectX)) ? -sv : sv);
    reading.summary = text;
    if (std::abs(su) < kTellable || std::abs(sv) < kTellable)
        reading.summary += " One axis has too little slope to be sure: check the preview.";
    return reading;
}

ReliefReading reliefByName(bool depthByName, const std::string& heightFile) {
    ReliefReading reading;
    reading.depth = depthByName;
    reading.summary = "Guessed from the file name " + fileName(heightFile) + ": read as " +
                      readingName(depthByName) +
                      ". There is no normal map to check it against: flip it if the relief "
                      "looks inverted.";
    return reading;
}

} // namespace px
