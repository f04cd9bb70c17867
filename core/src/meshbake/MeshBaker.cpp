#include "bake/BakeProgress.h"
#include "meshbake/AoDirections.h"
#include "meshbake/EmbreeTile.h"
#include "parallax/meshbake/MeshBake.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace px {

namespace {

using meshbake::EmbreeTile;

constexpr int kLanes = 8;
constexpr int kMaxSide = 32768;
constexpr int kMaxSamples = 16;
constexpr int kMaxRays = 4096;
// Surfaces below a first hit that face the other way (a closed sculpt's underside) are passed
// through up to this many times looking for one that faces the same way (an overhang).
constexpr int kOverhangLayers = 6;

// The first hit under one sub-sample.
struct Sample {
    glm::vec3 p;  // the hit point
    glm::vec3 n;  // shading normal, on the side seen from above
    glm::vec3 ng; // face normal, the same side
    bool hit = false;
};

// The tile's geometry of rays: where they start, how far they reach, the offsets off surfaces.
struct RayFrame {
    float top = 0;   // z the rays from above start at
    float reach = 0; // their tfar
    float eps = 0;   // offset off a surface (scene-relative: float positions carry ~1e-7)
};

RayFrame rayFrame(const BakeMesh& mesh, const BakeTile& tile) {
    const float extent = std::max({mesh.hi.z - mesh.lo.z, static_cast<float>(tile.width()),
                                   static_cast<float>(tile.height())});
    const float magnitude =
        std::max({std::abs(mesh.lo.x), std::abs(mesh.lo.y), std::abs(mesh.lo.z),
                  std::abs(mesh.hi.x), std::abs(mesh.hi.y), std::abs(mesh.hi.z), extent});
    RayFrame f;
    const float margin = 1e-3f * extent;
    f.top = mesh.hi.z + margin;
    f.reach = (mesh.hi.z - mesh.lo.z) + 2.0f * margin;
    f.eps = 2e-5f * magnitude;
    return f;
}

glm::vec3 vertex(const BakeMesh& m, unsigned i) {
    return {m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]};
}

// The face normal as wound (counter-clockwise seen from its front), unit length.
glm::vec3 faceNormal(const BakeMesh& m, unsigned prim) {
    const unsigned* t = &m.indices[3 * static_cast<std::size_t>(prim)];
    const glm::vec3 a = vertex(m, t[0]);
    return glm::normalize(glm::cross(vertex(m, t[1]) - a, vertex(m, t[2]) - a));
}

// Interpolated vertex normals at Embree's barycentrics (p = (1-u-v) p0 + u p1 + v p2), or the
// face normal where the mesh has none or they cancel.
glm::vec3 shadingNormal(const BakeMesh& m, unsigned prim, float u, float v, const glm::vec3& ng) {
    if (m.normals.empty())
        return ng;
    const unsigned* t = &m.indices[3 * static_cast<std::size_t>(prim)];
    auto n = [&m](unsigned i) {
        return glm::vec3(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]);
    };
    const glm::vec3 s = (1.0f - u - v) * n(t[0]) + u * n(t[1]) + v * n(t[2]);
    const float length = glm::length(s);
    return length > 1e-6f ? s / length : ng;
}

std::vector<glm::vec2> copyOffsets(const BakeTile& tile, WrapMode wrap) {
    std::vector<glm::vec2> offsets{{0.0f, 0.0f}};
    if (wrap == WrapMode::Repeat) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx != 0 || dy != 0)
                    offsets.emplace_back(static_cast<float>(dx * tile.width()),
                                         static_cast<float>(dy * tile.height()));
            }
        }
    }
    return offsets;
}

std::string tileText(const BakeTile& t) {
    std::ostringstream out;
    out << t.x0 << "," << t.y0 << "," << t.x1 << "," << t.y1;
    return out.str();
}

// Per thread: the range of the hits, the overhangs.
struct Tally {
    float lo = INFINITY, hi = -INFINITY;
    std::int64_t misses = 0, overhangs = 0;
};

class RowBaker {
public:
    RowBaker(const BakeMesh& mesh, const MeshBakeOptions& o, const EmbreeTile& tile,
             const RayFrame& frame)
        : m_mesh(mesh), m_o(o), m_scene(tile.scene()), m_frame(frame),
          m_directions(meshbake::hammersley(o.rays)) {}

    // Traces every sub-sample of texel row j into `samples` (K rows of W*K).
    void traceRow(int j, std::vector<Sample>& samples, Tally& tally) const {
        const int k = m_o.samples, across = m_o.width * k;
        samples.assign(static_cast<std::size_t>(across) * k, Sample{});
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        for (int b = 0; b < k; ++b) {
            const double v = (static_cast<double>(j) * k + b + 0.5) / (m_o.height * k);
            const auto y = static_cast<float>(m_o.tile.y1 - v * m_o.tile.height());
            for (int first = 0; first < across; first += kLanes)
                tracePacket(first, y, &samples[static_cast<std::size_t>(b) * across], context,
                            tally);
        }
    }

    // The visible fraction at texel (i, j) from its sub-samples' hits.
    float occlusion(int i, int j, const std::vector<Sample>& samples) const {
        const int k = m_o.samples, across = m_o.width * k, subs = k * k;
        const glm::vec2 shift = meshbake::texelShift(i, j, m_o.seed);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        alignas(32) RTCRay8 packet;
        alignas(32) int valid[kLanes];
        int queued = 0, open = 0;
        auto flush = [&] {
            for (int l = queued; l < kLanes; ++l)
                valid[l] = 0;
            rtcOccluded8(valid, m_scene, &context, &packet);
            for (int l = 0; l < queued; ++l)
                open += packet.tfar[l] >= 0.0f;
            queued = 0;
        };
        const float reach =
            std::isfinite(m_o.distance) ? static_cast<float>(m_o.distance) : INFINITY;
        for (int r = 0; r < m_o.rays; ++r) {
            const int s = r % subs;
            const Sample& at = samples[static_cast<std::size_t>(s / k) * across +
                                       static_cast<std::size_t>(i) * k + s % k];
            if (!at.hit) { // nothing there to occlude
                ++open;
                continue;
            }
            const glm::vec3 d = meshbake::cosineDirection(m_directions[r], shift, at.n);
            if (glm::dot(d, at.ng) <= 0.0f)
                continue; // into the surface itself
            // With repeat the surface covers the plane: a ray heading down crosses it before it
            // sinks below the lowest point, also where it would leave the copies first.
            if (m_o.wrap == WrapMode::Repeat && d.z < 0.0f &&
                (at.p.z - m_mesh.lo.z) <= reach * -d.z)
                continue;
            const glm::vec3 o = at.p + m_frame.eps * at.ng;
            packet.org_x[queued] = o.x;
            packet.org_y[queued] = o.y;
            packet.org_z[queued] = o.z;
            packet.dir_x[queued] = d.x;
            packet.dir_y[queued] = d.y;
            packet.dir_z[queued] = d.z;
            packet.tnear[queued] = 0.0f;
            // A ray that climbs above the mesh's top meets nothing more: it ends there.
            packet.tfar[queued] = d.z > 0.0f ? std::min(reach, (m_frame.top - o.z) / d.z) : reach;
            packet.time[queued] = 0.0f;
            packet.mask[queued] = 0xFFFFFFFFu;
            packet.id[queued] = 0;
            packet.flags[queued] = 0;
            valid[queued] = -1;
            if (++queued == kLanes)
                flush();
        }
        if (queued > 0)
            flush();
        return static_cast<float>(open) / static_cast<float>(m_o.rays);
    }

private:
    void tracePacket(int first, float y, Sample* row, RTCIntersectContext& context,
                     Tally& tally) const {
        const int across = m_o.width * m_o.samples;
        alignas(32) RTCRayHit8 rays;
        alignas(32) int valid[kLanes];
        for (int l = 0; l < kLanes; ++l) {
            const int sx = first + l;
            valid[l] = sx < across ? -1 : 0;
            const double u = (sx + 0.5) / across;
            rays.ray.org_x[l] = static_cast<float>(m_o.tile.x0 + u * m_o.tile.width());
            rays.ray.org_y[l] = y;
            rays.ray.org_z[l] = m_frame.top;
            rays.ray.dir_x[l] = 0.0f;
            rays.ray.dir_y[l] = 0.0f;
            rays.ray.dir_z[l] = -1.0f;
            rays.ray.tnear[l] = 0.0f;
            rays.ray.tfar[l] = m_frame.reach;
            rays.ray.time[l] = 0.0f;
            rays.ray.mask[l] = 0xFFFFFFFFu;
            rays.ray.id[l] = static_cast<unsigned>(l);
            rays.ray.flags[l] = 0;
            rays.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
            rays.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid, m_scene, &context, &rays);
        // Overhangs: a second packet goes on below each first hit.
        alignas(32) RTCRayHit8 below = rays;
        alignas(32) int again[kLanes];
        float side[kLanes];
        for (int l = 0; l < kLanes; ++l) {
            again[l] = 0;
            if (!valid[l])
                continue;
            Sample& s = row[first + l];
            if (rays.hit.geomID[l] == RTC_INVALID_GEOMETRY_ID) {
                ++tally.misses;
                continue;
            }
            const unsigned prim = rays.hit.primID[l];
            const glm::vec3 wound = faceNormal(m_mesh, prim);
            // Seen from above: the side facing up, whichever way the file winds it.
            side[l] = wound.z >= 0.0f ? 1.0f : -1.0f;
            s.ng = side[l] * wound;
            s.n = side[l] * shadingNormal(m_mesh, prim, rays.hit.u[l], rays.hit.v[l], wound);
            const float t = rays.ray.tfar[l];
            s.p = {rays.ray.org_x[l], y, m_frame.top - t};
            s.hit = true;
            tally.lo = std::min(tally.lo, s.p.z);
            tally.hi = std::max(tally.hi, s.p.z);
            again[l] = -1;
            below.ray.tnear[l] = t + m_frame.eps;
            below.ray.tfar[l] = m_frame.reach;
            below.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
            below.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
        }
        for (int layer = 0; layer < kOverhangLayers; ++layer) {
            if (std::none_of(again, again + kLanes, [](int a) { return a != 0; }))
                break;
            rtcIntersect8(again, m_scene, &context, &below);
            for (int l = 0; l < kLanes; ++l) {
                if (!again[l])
                    continue;
                again[l] = 0;
                if (below.hit.geomID[l] == RTC_INVALID_GEOMETRY_ID)
                    continue;
                const float facing = faceNormal(m_mesh, below.hit.primID[l]).z * side[l];
                if (facing > 0.0f) {
                    ++tally.overhangs; // another surface seen from above, under the top one
                    continue;
                }
                again[l] = -1; // an underside: look further down
                below.ray.tnear[l] = below.ray.tfar[l] + m_frame.eps;
                below.ray.tfar[l] = m_frame.reach;
                below.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
                below.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
            }
        }
    }

    const BakeMesh& m_mesh;
    const MeshBakeOptions& m_o;
    RTCScene m_scene;
    RayFrame m_frame;
    std::vector<glm::vec2> m_directions;
};

bool overlaps(const BakeMesh& mesh, const BakeTile& tile, const std::vector<glm::vec2>& offsets) {
    for (const glm::vec2& o : offsets) {
        if (mesh.lo.x + o.x < tile.x1 && mesh.hi.x + o.x > tile.x0 && mesh.lo.y + o.y < tile.y1 &&
            mesh.hi.y + o.y > tile.y0)
            return true;
    }
    return false;
}

} // namespace

BakeTile defaultTile(const BakeMesh& mesh) {
    return {mesh.lo.x, mesh.lo.y, mesh.hi.x, mesh.hi.y};
}

Status checkMeshBake(const BakeMesh& mesh, const MeshBakeOptions& o) {
    const BakeTile& t = o.tile;
    if (!std::isfinite(t.x0) || !std::isfinite(t.y0) || !std::isfinite(t.x1) ||
        !std::isfinite(t.y1) || !(t.x1 > t.x0) || !(t.y1 > t.y0))
        return Error{"the tile " + tileText(t) + " is empty: it needs x0 < x1 and y0 < y1"};
    if (o.width < 1 || o.height < 1 || o.width > kMaxSide || o.height > kMaxSide)
        return Error{"the bake's size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                     " is outside 1 to " + std::to_string(kMaxSide)};
    if (o.samples < 1 || o.samples > kMaxSamples)
        return Error{"samples " + std::to_string(o.samples) + " is outside 1 to " +
                     std::to_string(kMaxSamples)};
    if (o.maps.occlusion && (o.rays < 1 || o.rays > kMaxRays))
        return Error{"rays " + std::to_string(o.rays) + " is outside 1 to " +
                     std::to_string(kMaxRays)};
    if (!(o.distance > 0.0))
        return Error{"the occlusion distance must be greater than 0"};
    if (o.range &&
        !(o.range->z1 > o.range->z0 && std::isfinite(o.range->z0) && std::isfinite(o.range->z1)))
        return Error{"the height range needs z0 < z1"};
    if (mesh.indices.empty())
        return fileError(mesh.file, "has no triangles");
    if (!overlaps(mesh, t, copyOffsets(t, o.wrap))) {
        std::ostringstream bounds;
        bounds << mesh.lo.x << "," << mesh.lo.y << "," << mesh.hi.x << "," << mesh.hi.y;
        return fileError(mesh.file, "the tile " + tileText(t) +
                                        " holds no geometry (the mesh's XY bounds are " +
                                        bounds.str() + ")");
    }
    return success();
}

Result<MeshBakeResult> bakeFromMesh(const BakeMesh& mesh, const MeshBakeOptions& o,
                                    const BakeControl& control) {
    if (Status s = checkMeshBake(mesh, o); !s)
        return s.error();
    Result<EmbreeTile> tile = EmbreeTile::make(mesh, copyOffsets(o.tile, o.wrap));
    if (!tile)
        return tile.error();
    const RayFrame frame = rayFrame(mesh, o.tile);
    const RowBaker baker(mesh, o, *tile, frame);
    const int w = o.width, h = o.height, k = o.samples;

    MeshBakeResult out;
    out.copies = static_cast<int>(tile->offsets().size());
    out.samples = static_cast<std::int64_t>(w) * h * k * k;
    // The heights' sums per texel and their hit counts: the range is known only at the end.
    Image sums(w, h, 1);
    std::vector<std::uint16_t> hits(static_cast<std::size_t>(w) * h, 0);
    if (o.maps.normal)
        out.normal = Image(w, h, 3);
    if (o.maps.occlusion)
        out.occlusion = Image(w, h, 1);
    const PlaneWriter sum{sums.pixels.data(), w};
    const ImageWriter normal = o.maps.normal ? out.normal.writer() : ImageWriter{nullptr, w, 3};
    const PlaneWriter ao{o.maps.occlusion ? out.occlusion.pixels.data() : nullptr, w};
    const float green = o.green == NormalGreen::OpenGL ? 1.0f : -1.0f;

    BakeProgress progress(control, h);
    tbb::enumerable_thread_specific<Tally> tallies;
    tbb::enumerable_thread_specific<std::vector<Sample>> rows;
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 1), [&](const tbb::blocked_range<int>& range) {
        Tally& tally = tallies.local();
        std::vector<Sample>& samples = rows.local();
        for (int j = range.begin(); j != range.end(); ++j) {
            if (progress.stopRequested())
                return; // cancelled: between slices
            baker.traceRow(j, samples, tally);
            const int across = w * k;
            for (int i = 0; i < w; ++i) {
                float z = 0.0f;
                int count = 0;
                glm::vec3 n(0.0f);
                for (int b = 0; b < k; ++b) {
                    for (int a = 0; a < k; ++a) {
                        const Sample& s = samples[static_cast<std::size_t>(b) * across +
                                                  static_cast<std::size_t>(i) * k + a];
                        if (!s.hit)
                            continue;
                        z += s.p.z;
                        n += s.n;
                        ++count;
                    }
                }
                sum.at(i, j) = z;
                hits[static_cast<std::size_t>(j) * w + i] = static_cast<std::uint16_t>(count);
                if (o.maps.normal) {
                    const float length = glm::length(n);
                    n = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
                    normal.at(i, j, 0) = n.x * 0.5f + 0.5f;
                    normal.at(i, j, 1) = green * n.y * 0.5f + 0.5f;
                    normal.at(i, j, 2) = n.z * 0.5f + 0.5f;
                }
                if (o.maps.occlusion)
                    ao.at(i, j) = baker.occlusion(i, j, samples);
            }
            progress.advance(1);
        }
    });
    if (progress.stopRequested())
        return cancelledError();

    Tally all;
    for (const Tally& t : tallies) {
        all.lo = std::min(all.lo, t.lo);
        all.hi = std::max(all.hi, t.hi);
        all.misses += t.misses;
        all.overhangs += t.overhangs;
    }
    out.misses = all.misses;
    out.overhangs = all.overhangs;
    if (all.misses == out.samples)
        return fileError(mesh.file, "no ray from above met the mesh inside the tile " +
                                        tileText(o.tile) + " (thinner than a sample?)");
    if (o.range) {
        // A hit outside the given range would be clamped: say so instead.
        const double slack = 1e-6 * std::max(1.0, o.range->z1 - o.range->z0);
        if (all.lo < o.range->z0 - slack || all.hi > o.range->z1 + slack) {
            std::ostringstream text;
            text << "the surface reaches z = " << all.lo << " to " << all.hi
                 << ", outside the range " << o.range->z0 << "," << o.range->z1;
            return fileError(mesh.file, text.str());
        }
        out.range = *o.range;
    } else {
        out.range = {all.lo, all.hi};
    }
    out.heightScale = (out.range.z1 - out.range.z0) / o.tile.width();
    if (o.maps.height) {
        // Misses count as the range's minimum (height 0); a flat range puts every hit at 1.
        const auto subs = static_cast<float>(k * k);
        const auto z0 = static_cast<float>(out.range.z0);
        const auto span = static_cast<float>(out.range.z1 - out.range.z0);
        float* z = sums.pixels.data();
        for (std::size_t t = 0; t < hits.size(); ++t) {
            const float count = hits[t];
            const float mapped = span > 0.0f ? (z[t] - count * z0) / (subs * span) : count / subs;
            z[t] = std::clamp(mapped, 0.0f, 1.0f); // rounding only: hits lie in the range
        }
        out.height = std::move(sums);
    }
    progress.finish();
    return out;
}

} // namespace px
