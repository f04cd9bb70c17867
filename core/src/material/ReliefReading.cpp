#include "parallax/material/ReliefReading.h"

#include "parallax/bake/NormalMapBaker.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace px {

namespace {

// Below this a slope correlation says nothing (noise, or another set's normal map).
constexpr double kTellable = 0.2;

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
    const SlopeCorrelation slopes = correlateWithSlopes(normals, file, wrap);
    ReliefReading reading;
    reading.slopeU = slopes.across;
    reading.slopeV = slopes.down;
    if (std::abs(reading.slopeU) < kTellable && std::abs(reading.slopeV) < kTellable) {
        reading = reliefByName(depthByName, "");
        reading.slopeU = slopes.across;
        reading.slopeV = slopes.down;
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
