#include "parallax/eval/StabilitySuite.h"

#include "RayBatch.h"
#include "StabilityCases.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/OutputGate.h"
#include "parallax/trace/TraceScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>

namespace px {
namespace {

using stability::CaseSpec;
using stability::Reference;
using stability::Special;

std::string format(const char* fmt, double value) {
    char text[48];
    std::snprintf(text, sizeof text, fmt, value);
    return text;
}

// Bilinear height in double precision (docs/conventions.md §1), independent of the kernels.
double bilinear(const HeightField& f, WrapMode wrap, double u, double v) {
    const double X = u * f.width - 0.5, Y = v * f.height - 0.5;
    const double x0 = std::floor(X), y0 = std::floor(Y);
    const double fx = X - x0, fy = Y - y0;
    auto h = [&](double x, double y) {
        return static_cast<double>(f.at(wrapIndex(static_cast<int>(x), f.width, wrap),
                                        wrapIndex(static_cast<int>(y), f.height, wrap)));
    };
    return (h(x0, y0) * (1 - fx) + h(x0 + 1, y0) * fx) * (1 - fy) +
           (h(x0, y0 + 1) * (1 - fx) + h(x0 + 1, y0 + 1) * fx) * fy;
}

// What one case traces with: its map and the cone maps its techniques read.
struct CaseSetup {
    HeightField field;
    std::shared_ptr<const ConeMap> cone, relaxedCone;
};

CaseSetup setUp(const CaseSpec& spec, unsigned seed) {
    CaseSetup s;
    s.field = makeProceduralMap(spec.map, spec.width, spec.height, seed, spec.level);
    if (spec.special == Special::ZeroCones) {
        auto relaxed = std::make_shared<ConeMap>(ConeKind::Relaxed, s.field.width, s.field.height);
        std::fill(relaxed->sqrtRatio.begin(), relaxed->sqrtRatio.end(), 0.0f);
        auto cone =
            std::make_shared<ConeMap>(ConeKind::Conservative, s.field.width, s.field.height);
        std::fill(cone->sqrtRatio.begin(), cone->sqrtRatio.end(), 0.0f);
        s.cone = cone;
        s.relaxedCone = relaxed;
    } else if (spec.special == Special::ForeignCones) {
        // The cones of a flat map: the widest there are, wrong everywhere the map rises.
        const HeightField flat(spec.width, spec.height, 0.0f);
        s.cone = std::make_shared<ConeMap>(bakeConeMap(flat, spec.wrap, ConeKind::Conservative));
        s.relaxedCone = std::make_shared<ConeMap>(bakeConeMap(flat, spec.wrap, ConeKind::Relaxed));
    }
    return s;
}

// One view of a case: its rays and what the bound rules need to know about them.
struct ViewSetup {
    TraceScene scene;
    glm::vec2 P{0.0f};
    stability::CaseGeometry geometry;
};

ViewSetup setUpView(const CaseSpec& spec, const HeightField& field, int rays,
                    const stability::View& view) {
    ViewSetup v;
    v.scene.rays = rays;
    v.scene.polarDeg = view.polarDeg;
    v.scene.azimuthDeg = view.azimuthDeg;
    v.scene.uvOffset = spec.uvOffset;
    v.P = parallaxVector(spec.scale, view.polarDeg, view.azimuthDeg);
    const double start = std::clamp(1.0 - field.maxHeight(), 0.0, 1.0);
    v.geometry.rayTexels = std::hypot(static_cast<double>(v.P.x) * field.width,
                                      static_cast<double>(v.P.y) * field.height) *
                           (1.0 - start);
    v.geometry.rayTiles =
        std::hypot(static_cast<double>(v.P.x), static_cast<double>(v.P.y)) * (1.0 - start);
    v.geometry.cosTheta = std::cos(view.polarDeg * 3.14159265358979323846 / 180.0);
    return v;
}

// A constant surface's hits: t = 1 - h along each ray (h is the same everywhere).
std::vector<TraceResult> closedFormHits(const HeightField& field, const ViewSetup& v,
                                        WrapMode wrap) {
    std::vector<TraceResult> hits;
    const int R = v.scene.rays;
    for (int j = 0; j < R; ++j) {
        for (int i = 0; i < R; ++i) {
            const glm::dvec2 uv0 = rayOrigin(v.scene, i, j);
            TraceResult r;
            r.t = static_cast<float>(1.0 - bilinear(field, wrap, uv0.x, uv0.y));
            r.u = uv0.x + static_cast<double>(v.P.x) * r.t;
            r.v = uv0.y + static_cast<double>(v.P.y) * r.t;
            hits.push_back(r);
        }
    }
    return hits;
}

bool techniqueApplies(const CaseSpec& spec, Technique t) {
    if (spec.special == Special::ZeroCones || spec.special == Special::ForeignCones)
        return t == Technique::Cone || t == Technique::RelaxedCone;
    return info(t).parallax;
}

void checkStability(StabilityRow& row) {
    if (row.stats.invalid > 0)
        row.failure = std::to_string(row.stats.invalid) + " rays NaN, infinite or t outside [0, 1]";
    else if (row.stats.maxFetches > row.fetchCap)
        row.failure = std::to_string(row.stats.maxFetches) + " fetches over the cap of " +
                      std::to_string(row.fetchCap);
}

StabilityRow nanInFloatMapRow(const CaseSpec& spec) {
    StabilityRow row;
    row.caseName = std::string(spec.info.name);
    row.technique = "loader";
    namespace fs = std::filesystem;
    std::error_code ec;
    // A folder of its own (mkdtemp), so that removing it afterwards removes nobody else's files.
    std::string pattern = (fs::temp_directory_path(ec) / "parallax-stability-XXXXXX").string();
    const fs::path dir = ::mkdtemp(pattern.data()) != nullptr ? fs::path(pattern) : fs::path();
    const std::string file = (dir / "nan-height.exr").string();
    Image image(spec.width, spec.height, 1);
    image.at(3, 2) = std::numeric_limits<float>::quiet_NaN();
    ImageWriteOptions write;
    write.format = PixelFormat::Float;
    if (dir.empty()) {
        row.failure = "could not create a temporary folder for the test file";
    } else if (Status s = writeImage(file, image, write); !s) {
        row.failure = "could not write the test file: " + s.error().message;
    } else {
        Result<HeightField> loaded = loadHeightField(file);
        if (loaded) {
            row.failure = "the NaN map was accepted";
        } else {
            const std::string& message = loaded.error().message;
            row.figure = "refused: " + message.substr(message.find(": ") + 2);
            if (message.find("NaN") == std::string::npos ||
                message.find("(3, 2)") == std::string::npos)
                row.failure = "the message does not say NaN at texel (3, 2)";
        }
    }
    if (!dir.empty())
        discardTemporary(dir);
    row.passed = row.failure.empty();
    return row;
}

// One technique's hits over every view of a case, and the hits it is held to.
struct PooledHits {
    std::vector<TraceResult> hits, expected;
};

Result<PooledHits> traceViews(const CaseSpec& spec, const Tracer& tracer,
                              const std::vector<ViewSetup>& views,
                              const std::vector<std::vector<TraceResult>>& references,
                              const EvalControl& control) {
    PooledHits pooled;
    for (std::size_t k = 0; k < views.size(); ++k) {
        std::vector<TraceResult> hits, expected = references[k];
        if (!traceBatch(tracer, views[k].scene, RayTiming::Parallel, hits, control.cancel))
            return evaluationCancelled();
        if (spec.special == Special::FarOrigin) {
            // The reference: the same technique near the origin, moved by the whole tiles.
            TraceScene near = views[k].scene;
            near.uvOffset = {0.0, 0.0};
            if (!traceBatch(tracer, near, RayTiming::Parallel, expected, control.cancel))
                return evaluationCancelled();
            for (TraceResult& r : expected) {
                r.u += spec.uvOffset.x;
                r.v += spec.uvOffset.y;
            }
        }
        pooled.hits.insert(pooled.hits.end(), hits.begin(), hits.end());
        pooled.expected.insert(pooled.expected.end(), expected.begin(), expected.end());
    }
    return pooled;
}

Result<std::vector<StabilityRow>> runCase(const CaseSpec& spec, const StabilityOptions& options,
                                          const EvalControl& control) {
    if (spec.special == Special::NanInFloatMap)
        return std::vector<StabilityRow>{nanInFloatMapRow(spec)};
    const CaseSetup s = setUp(spec, options.seed);
    TraceMaps maps;
    maps.height = &s.field;
    maps.wrap = spec.wrap;
    maps.cone = s.cone.get();
    maps.relaxedCone = s.relaxedCone.get();

    // The views, the longest ray among them (for the bounds and the fetch caps), and the
    // reference hits of each.
    std::vector<ViewSetup> views;
    stability::CaseGeometry longest;
    long long rayCells = 0;
    for (const stability::View& view : stability::caseViews(spec)) {
        views.push_back(setUpView(spec, s.field, options.rays, view));
        const stability::CaseGeometry& g = views.back().geometry;
        if (g.rayTexels >= longest.rayTexels)
            longest = g;
        rayCells = std::max(rayCells, rayCellBound(views.back().P, s.field.width, s.field.height));
    }
    Result<Tracer> exact =
        Tracer::create(maps, Technique::Exact, info(Technique::Exact).defaults, spec.scale);
    if (!exact)
        return exact.error();
    std::vector<std::vector<TraceResult>> references(views.size());
    for (std::size_t k = 0; k < views.size(); ++k) {
        if (!traceBatch(*exact, views[k].scene, RayTiming::Parallel, references[k], control.cancel))
            return evaluationCancelled();
        if (spec.reference == Reference::ClosedForm || spec.scale == 0.0f)
            references[k] = closedFormHits(s.field, views[k], spec.wrap);
    }

    std::vector<StabilityRow> rows;
    for (const TechniqueInfo& ti : allTechniques()) {
        if (!techniqueApplies(spec, ti.id))
            continue;
        Result<Tracer> tracer = Tracer::create(maps, ti.id, ti.defaults, spec.scale);
        if (!tracer)
            return tracer.error();
        Result<PooledHits> pooled = traceViews(spec, *tracer, views, references, control);
        if (!pooled)
            return pooled.error();
        StabilityRow row;
        row.caseName = std::string(spec.info.name);
        row.technique = std::string(ti.name);
        row.stats = measureHits(pooled->hits, pooled->expected, s.field.width, s.field.height);
        row.fetchCap = spec.scale == 0.0f ? 1 : fetchCap(ti.id, ti.defaults, rayCells);
        row.bound = stability::boundFor(spec, ti.id, ti.defaults, longest);
        const BoundCheck check =
            checkBound(row.bound, pooled->hits, pooled->expected, s.field.width, s.field.height);
        row.figure = check.figure + "; fetches <= " + std::to_string(row.stats.maxFetches) +
                     " of " + std::to_string(row.fetchCap);
        row.failure = check.failure;
        checkStability(row);
        row.passed = row.failure.empty();
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace

BoundCheck checkBound(const ErrorBound& b, std::span<const TraceResult> hits,
                      std::span<const TraceResult> reference, int width, int height) {
    BoundCheck c;
    const HitErrorStats stats = measureHits(hits, reference, width, height);
    const std::string limit = format("%.3g", b.limit);
    switch (b.kind) {
    case BoundKind::None:
        c.figure = "no bound: " + b.rule;
        break;
    case BoundKind::MaxTexels:
        c.figure = "max " + format("%.3g", stats.maxError) + " <= " + limit + " texels";
        if (!(stats.maxError <= b.limit))
            c.failure = "error above the bound";
        break;
    case BoundKind::P99Texels:
        c.figure = "p99 " + format("%.3g", stats.p99Error) + " <= " + limit + " texels";
        if (!(stats.p99Error <= b.limit))
            c.failure = "p99 error above the bound";
        break;
    case BoundKind::NoOvershoot: {
        double worst = 0.0;
        for (std::size_t k = 0; k < hits.size(); ++k) {
            if (hits[k].t > reference[k].t)
                worst = std::max(worst, hitErrorTexels(hits[k], reference[k], width, height));
        }
        c.figure = "overshoot " + format("%.3g", worst) + " <= " + limit + " texels";
        if (!(worst <= b.limit))
            c.failure = "a ray ended past the hit";
        break;
    }
    case BoundKind::MaxDepth: {
        double worst = 0.0;
        for (std::size_t k = 0; k < hits.size(); ++k)
            worst = std::max(worst, std::abs(static_cast<double>(hits[k].t) - reference[k].t));
        c.figure = "|t - (1 - h)| " + format("%.3g", worst) + " <= " + limit;
        if (!(worst <= b.limit))
            c.failure = "t differs from 1 - h(uv0)";
        break;
    }
    }
    // Beside the bound, always the whole distribution's tail: p99 hides a few rays far off.
    c.figure += " (p99 " + format("%.3g", stats.p99Error) + ", max " +
                format("%.3g", stats.maxError) + ", " + std::to_string(stats.wrongSurface) +
                " rays > " + format("%g", kWrongSurfaceTexels) + " texels)";
    return c;
}

bool suitePassed(const std::vector<StabilityRow>& rows) {
    return std::all_of(rows.begin(), rows.end(), [](const StabilityRow& r) { return r.passed; });
}

Result<std::vector<StabilityRow>> runStabilitySuite(const StabilityOptions& options,
                                                    const EvalControl& control) {
    if (options.rays < 1 || options.rays > 1024)
        return Error{"rays must be 1 to 1024 per side, not " + std::to_string(options.rays)};
    std::vector<const CaseSpec*> selected;
    for (const std::string& name : options.cases) {
        const auto specs = stability::caseSpecs();
        auto it = std::find_if(specs.begin(), specs.end(),
                               [&](const CaseSpec& c) { return c.info.name == name; });
        if (it == specs.end())
            return Error{"unknown stability case '" + name + "'"};
        selected.push_back(&*it);
    }
    if (selected.empty()) {
        for (const CaseSpec& c : stability::caseSpecs())
            selected.push_back(&c);
    }

    std::vector<StabilityRow> rows;
    EvalProgress progress;
    progress.total = static_cast<int>(selected.size());
    for (const CaseSpec* spec : selected) {
        if (control.cancelled())
            return evaluationCancelled();
        Result<std::vector<StabilityRow>> caseRows = runCase(*spec, options, control);
        if (!caseRows && isEvaluationCancelled(caseRows.error()))
            return caseRows.error();
        if (!caseRows)
            return fileError(std::string(spec->info.name), caseRows.error().message);
        for (StabilityRow& r : *caseRows)
            rows.push_back(std::move(r));
        ++progress.done;
        progress.stage = std::string(spec->info.name);
        if (control.progress)
            control.progress(progress);
    }
    return rows;
}

} // namespace px
