#include "meshbake/EmbreeTile.h"

#include <utility>

namespace px::meshbake {

namespace {

void recordError(void* user, RTCError code, const char* text) {
    if (code != RTC_ERROR_NONE)
        *static_cast<std::string*>(user) = text != nullptr ? text : "unknown error";
}

} // namespace

EmbreeTile::EmbreeTile(EmbreeTile&& other) noexcept
    : m_device(std::exchange(other.m_device, nullptr)),
      m_mesh(std::exchange(other.m_mesh, nullptr)), m_top(std::exchange(other.m_top, nullptr)),
      m_offsets(std::move(other.m_offsets)), m_error(std::move(other.m_error)) {
    // The error callback points at the string: give it this object's.
    if (m_device != nullptr)
        rtcSetDeviceErrorFunction(m_device, recordError, &m_error);
}

EmbreeTile::~EmbreeTile() {
    if (m_top != nullptr)
        rtcReleaseScene(m_top);
    if (m_mesh != nullptr)
        rtcReleaseScene(m_mesh);
    if (m_device != nullptr)
        rtcReleaseDevice(m_device);
}

Result<EmbreeTile> EmbreeTile::make(const BakeMesh& mesh, const std::vector<glm::vec2>& offsets) {
    EmbreeTile tile;
    tile.m_offsets = offsets;
    tile.m_device = rtcNewDevice(nullptr);
    if (tile.m_device == nullptr)
        return Error{"Embree could not start (" +
                     std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")"};
    rtcSetDeviceErrorFunction(tile.m_device, recordError, &tile.m_error);
    auto failed = [&tile](const char* what) {
        return Error{std::string("Embree: ") + what + ": " +
                     (tile.m_error.empty() ? "unknown error" : tile.m_error)};
    };

    tile.m_mesh = rtcNewScene(tile.m_device);
    // Compact: leaves that index the shared vertices instead of copying them. On a 2M-triangle
    // tile it took the peak from 323 to 197 MB at the same speed (docs/bakers.md).
    rtcSetSceneFlags(tile.m_mesh,
                     static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT));
    RTCGeometry triangles = rtcNewGeometry(tile.m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // The loaded arrays themselves: BakeMesh pads positions with one float for Embree's 16-byte
    // reads.
    rtcSetSharedGeometryBuffer(triangles, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               mesh.positions.data(), 0, 3 * sizeof(float), mesh.vertexCount());
    rtcSetSharedGeometryBuffer(triangles, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               mesh.indices.data(), 0, 3 * sizeof(unsigned), mesh.triangleCount());
    rtcCommitGeometry(triangles);
    rtcAttachGeometryByID(tile.m_mesh, triangles, 0);
    rtcReleaseGeometry(triangles);
    rtcCommitScene(tile.m_mesh);
    if (!tile.m_error.empty())
        return failed("building the mesh's hierarchy");

    tile.m_top = rtcNewScene(tile.m_device);
    rtcSetSceneFlags(tile.m_top, RTC_SCENE_FLAG_ROBUST);
    for (unsigned i = 0; i < offsets.size(); ++i) {
        RTCGeometry copy = rtcNewGeometry(tile.m_device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(copy, tile.m_mesh);
        const float xfm[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, offsets[i].x, offsets[i].y, 0};
        rtcSetGeometryTransform(copy, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        rtcCommitGeometry(copy);
        rtcAttachGeometryByID(tile.m_top, copy, i);
        rtcReleaseGeometry(copy);
    }
    rtcCommitScene(tile.m_top);
    if (!tile.m_error.empty())
        return failed("building the tile's copies");
    return tile;
}

} // namespace px::meshbake
