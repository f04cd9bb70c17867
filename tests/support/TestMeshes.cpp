#include "TestMeshes.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

namespace px::test {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

void addGridTriangles(TestMesh& m, int columns, int rows, bool outwardAbc) {
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const unsigned a = j * (columns + 1) + i, b = a + 1, c = a + columns + 1, d = c + 1;
            if (outwardAbc)
                m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
            else
                m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    }
}

// The sphere's point, normal and derivatives by angle; columns wrap exactly (i % columns).
struct SpherePoint {
    glm::vec3 p, dPhi, dTheta;
};
SpherePoint spherePoint(int i, int j, int columns, int rows) {
    const float phi = 2.0f * kPi * static_cast<float>(i % columns) / columns;
    const float theta = kPi * (1e-3f + static_cast<float>(j) / rows * (1.0f - 2e-3f));
    return {{std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)},
            {std::sin(theta) * std::cos(phi), 0.0f, -std::sin(theta) * std::sin(phi)},
            {std::cos(theta) * std::sin(phi), -std::sin(theta), std::cos(theta) * std::cos(phi)}};
}

TestMesh sphere(int columns, int rows, bool mirrored) {
    TestMesh m;
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= columns; ++i) {
            const SpherePoint s = spherePoint(i, j, columns, rows);
            const float f = static_cast<float>(i) / columns;
            // Mirrored: u = 4 min(f, 1 - f), so du/dphi = +-2 / pi.
            const float u = mirrored ? 4.0f * std::min(f, 1.0f - f) : 2.0f * f;
            const float dPhiDu = mirrored ? (f <= 0.5f ? 0.5f * kPi : -0.5f * kPi) : kPi;
            m.positions.push_back(s.p);
            m.normals.push_back(s.p);
            m.uvs.emplace_back(u, static_cast<float>(j) / rows);
            m.dPdu.push_back(s.dPhi * dPhiDu);
            m.dPdv.push_back(s.dTheta * kPi * (1.0f - 2e-3f));
        }
    }
    addGridTriangles(m, columns, rows, false);
    return m;
}

template <typename T> void append(std::vector<std::uint8_t>& bytes, const std::vector<T>& data) {
    const std::size_t at = bytes.size();
    bytes.resize(at + data.size() * sizeof(T));
    if (!data.empty())
        std::memcpy(bytes.data() + at, data.data(), data.size() * sizeof(T));
}

bool writeBytes(const std::string& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    return static_cast<bool>(out);
}

// The document and its one buffer; `uri` empty for GLB.
nlohmann::json gltfDocument(const TestMesh& m, std::vector<std::uint8_t>& buffer,
                            const std::string& uri) {
    nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();
    nlohmann::json attributes = nlohmann::json::object();
    auto add = [&](const auto& data, const char* type, int components, int target) {
        const std::size_t offset = buffer.size();
        append(buffer, data);
        views.push_back({{"buffer", 0},
                         {"byteOffset", offset},
                         {"byteLength", buffer.size() - offset},
                         {"target", target}});
        accessors.push_back({{"bufferView", views.size() - 1},
                             {"componentType", target == 34963 ? 5125 : 5126},
                             {"count", data.size() * sizeof(data[0]) / (4 * components)},
                             {"type", type}});
        return accessors.size() - 1;
    };
    attributes["POSITION"] = add(m.positions, "VEC3", 3, 34962);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : m.positions) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    accessors.back()["min"] = {lo.x, lo.y, lo.z};
    accessors.back()["max"] = {hi.x, hi.y, hi.z};
    attributes["NORMAL"] = add(m.normals, "VEC3", 3, 34962);
    if (!m.uvs.empty())
        attributes["TEXCOORD_0"] = add(m.uvs, "VEC2", 2, 34962);
    if (!m.uvs2.empty())
        attributes["TEXCOORD_1"] = add(m.uvs2, "VEC2", 2, 34962);
    if (!m.tangents.empty())
        attributes["TANGENT"] = add(m.tangents, "VEC4", 4, 34962);
    const std::size_t indices = add(m.indices, "SCALAR", 1, 34963);
    nlohmann::json node = {{"mesh", 0}};
    if (m.nodeScale != glm::vec3(1.0f))
        node["scale"] = {m.nodeScale.x, m.nodeScale.y, m.nodeScale.z};
    nlohmann::json bufferEntry = {{"byteLength", buffer.size()}};
    if (!uri.empty())
        bufferEntry["uri"] = uri;
    return {{"asset", {{"version", "2.0"}, {"generator", "parallax-studio tests"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {node}},
            {"meshes",
             {{{"primitives", {{{"attributes", attributes}, {"indices", indices}, {"mode", 4}}}}}}},
            {"buffers", {bufferEntry}},
            {"bufferViews", views},
            {"accessors", accessors}};
}

} // namespace

TestMesh torus(int rings, int sides, bool withTangents, float tangentTurnDeg) {
    TestMesh m;
    const float R = 1.0f, r = 0.4f;
    for (int j = 0; j <= sides; ++j) {
        for (int i = 0; i <= rings; ++i) {
            const float phi = 2.0f * kPi * static_cast<float>(i % rings) / rings;
            const float theta = 2.0f * kPi * static_cast<float>(j % sides) / sides;
            const glm::vec3 n(std::cos(theta) * std::sin(phi), std::sin(theta),
                              std::cos(theta) * std::cos(phi));
            const float ring = R + r * std::cos(theta);
            m.positions.emplace_back(ring * std::sin(phi), r * std::sin(theta),
                                     ring * std::cos(phi));
            m.normals.push_back(n);
            // u = 3 phi / 2pi, v = 1 - theta / 2pi: upright from outside.
            m.uvs.emplace_back(3.0f * static_cast<float>(i) / rings,
                               1.0f - static_cast<float>(j) / sides);
            m.dPdu.push_back(glm::vec3(std::cos(phi), 0.0f, -std::sin(phi)) * ring * 2.0f * kPi /
                             3.0f);
            m.dPdv.push_back(glm::vec3(-std::sin(theta) * std::sin(phi), std::cos(theta),
                                       -std::sin(theta) * std::cos(phi)) *
                             r * -2.0f * kPi);
            if (withTangents) {
                const glm::vec3 t = glm::normalize(m.dPdu.back());
                const float a = tangentTurnDeg * kPi / 180.0f;
                m.tangents.emplace_back(std::cos(a) * t + std::sin(a) * glm::cross(n, t), 1.0f);
            }
        }
    }
    addGridTriangles(m, rings, sides, true);
    return m;
}

TestMesh seamedSphere(int columns, int rows) {
    return sphere(columns, rows, false);
}

TestMesh mirroredSphere(int columns, int rows) {
    return sphere(columns, rows, true);
}

TestMesh scaled(TestMesh m, glm::vec3 scale) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        m.positions[i] *= scale;
        m.normals[i] = glm::normalize(m.normals[i] / scale);
        if (i < m.dPdu.size()) {
            m.dPdu[i] *= scale;
            m.dPdv[i] *= scale;
        }
        if (i < m.tangents.size())
            m.tangents[i] =
                glm::vec4(glm::normalize(glm::vec3(m.tangents[i]) * scale), m.tangents[i].w);
    }
    return m;
}

TestMesh withDegenerateTriangles(TestMesh m) {
    auto vertex = [&](glm::vec3 p, glm::vec2 uv) {
        m.positions.push_back(p);
        m.normals.emplace_back(0.0f, 1.0f, 0.0f);
        m.uvs.push_back(uv);
        if (!m.uvs2.empty())
            m.uvs2.push_back(uv);
        if (!m.tangents.empty())
            m.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
        if (!m.dPdu.empty()) {
            m.dPdu.emplace_back(0.0f);
            m.dPdv.emplace_back(0.0f);
        }
        return static_cast<unsigned>(m.positions.size() - 1);
    };
    m.indices.insert(m.indices.end(), {0, 0, 1}); // a repeated corner
    const unsigned a = vertex({0.0f, 2.0f, 0.0f}, {0.1f, 0.1f});
    const unsigned b = vertex({0.1f, 2.0f, 0.0f}, {0.2f, 0.15f});
    const unsigned c = vertex({0.2f, 2.0f, 0.0f}, {0.1f, 0.3f}); // on the line through a and b
    m.indices.insert(m.indices.end(), {a, b, c});
    const unsigned d = vertex({0.0f, 2.0f, 0.5f}, {0.5f, 0.5f});
    const unsigned e = vertex({0.5f, 2.0f, 0.5f}, {0.5f, 0.5f});
    const unsigned f = vertex({0.0f, 2.5f, 0.5f}, {0.5f, 0.5f}); // no uv area
    m.indices.insert(m.indices.end(), {d, e, f});
    return m;
}

bool writeObj(const std::string& path, const TestMesh& m) {
    std::ofstream out(path);
    out << "# generated by the parallax-studio mesh tests\n";
    out.precision(9);
    for (const glm::vec3& p : m.positions)
        out << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const glm::vec2& uv : m.uvs)
        out << "vt " << uv.x << " " << 1.0f - uv.y << "\n"; // OBJ's v runs up
    for (const glm::vec3& n : m.normals)
        out << "vn " << n.x << " " << n.y << " " << n.z << "\n";
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        out << "f";
        for (int k = 0; k < 3; ++k) {
            const unsigned v = m.indices[i + k] + 1;
            if (m.uvs.empty())
                out << " " << v << "//" << v;
            else
                out << " " << v << "/" << v << "/" << v;
        }
        out << "\n";
    }
    return static_cast<bool>(out);
}

bool writeGltf(const std::string& path, const TestMesh& m) {
    std::vector<std::uint8_t> buffer;
    const std::filesystem::path file(path);
    if (file.extension() == ".glb") {
        std::string json = gltfDocument(m, buffer, {}).dump();
        json.resize((json.size() + 3) / 4 * 4, ' ');
        buffer.resize((buffer.size() + 3) / 4 * 4, 0);
        const auto u32 = [](std::size_t v) { return static_cast<std::uint32_t>(v); };
        const std::uint32_t header[3] = {0x46546C67u, 2u,
                                         u32(12 + 8 + json.size() + 8 + buffer.size())};
        const std::uint32_t jsonChunk[2] = {u32(json.size()), 0x4E4F534Au};
        const std::uint32_t binChunk[2] = {u32(buffer.size()), 0x004E4942u};
        std::vector<std::uint8_t> bytes;
        bytes.insert(bytes.end(), reinterpret_cast<const std::uint8_t*>(header),
                     reinterpret_cast<const std::uint8_t*>(header) + sizeof(header));
        bytes.insert(bytes.end(), reinterpret_cast<const std::uint8_t*>(jsonChunk),
                     reinterpret_cast<const std::uint8_t*>(jsonChunk) + sizeof(jsonChunk));
        bytes.insert(bytes.end(), json.begin(), json.end());
        bytes.insert(bytes.end(), reinterpret_cast<const std::uint8_t*>(binChunk),
                     reinterpret_cast<const std::uint8_t*>(binChunk) + sizeof(binChunk));
        bytes.insert(bytes.end(), buffer.begin(), buffer.end());
        return writeBytes(path, bytes.data(), bytes.size());
    }
    const std::string bin = file.stem().string() + ".bin";
    const std::string json = gltfDocument(m, buffer, bin).dump(1);
    return writeBytes((file.parent_path() / bin).string(), buffer.data(), buffer.size()) &&
           writeBytes(path, json.data(), json.size());
}

} // namespace px::test
