#include "BakeTiles.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <glm/geometric.hpp>
#include <numbers>

namespace px::test {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

glm::vec3 f(glm::dvec3 v) {
    return glm::vec3(v);
}

} // namespace

double periodicGroundZ(const TileRect& t, double a, double phase, double x, double y) {
    const double u = (x - t.x0) / t.width(), v = (y - t.y0) / t.height();
    return a * std::sin(kTwoPi * u + phase) * std::cos(kTwoPi * v);
}

glm::dvec3 periodicGroundNormal(const TileRect& t, double a, double phase, double x, double y) {
    const double u = (x - t.x0) / t.width(), v = (y - t.y0) / t.height();
    const double dzdx =
        a * kTwoPi / t.width() * std::cos(kTwoPi * u + phase) * std::cos(kTwoPi * v);
    const double dzdy =
        -a * kTwoPi / t.height() * std::sin(kTwoPi * u + phase) * std::sin(kTwoPi * v);
    return glm::normalize(glm::dvec3(-dzdx, -dzdy, 1.0));
}

TestMesh periodicGround(const TileRect& t, int n, double a, double phase) {
    TestMesh m;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double x = t.x0 + t.width() * i / n, y = t.y0 + t.height() * j / n;
            m.positions.push_back(f({x, y, periodicGroundZ(t, a, phase, x, y)}));
            m.normals.push_back(f(periodicGroundNormal(t, a, phase, x, y)));
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<unsigned>(j * (n + 1) + i), r = static_cast<unsigned>(n + 1);
            m.indices.insert(m.indices.end(), {v, v + 1, v + r + 1, v, v + r + 1, v + r});
        }
    }
    return m;
}

TestMesh flatGround(const TileRect& rect, int n, double height) {
    TestMesh m;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            m.positions.push_back(
                f({rect.x0 + rect.width() * i / n, rect.y0 + rect.height() * j / n, height}));
            m.normals.emplace_back(0.0f, 0.0f, 1.0f);
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<unsigned>(j * (n + 1) + i), r = static_cast<unsigned>(n + 1);
            m.indices.insert(m.indices.end(), {v, v + 1, v + r + 1, v, v + r + 1, v + r});
        }
    }
    return m;
}

TestMesh dome(glm::dvec3 c, double radius, int segments, int rings) {
    TestMesh m;
    // Ring 0 is the rim (polar angle 90 degrees), ring `rings` the pole (one vertex).
    for (int r = 0; r < rings; ++r) {
        const double polar = 0.5 * std::numbers::pi * (1.0 - static_cast<double>(r) / rings);
        for (int s = 0; s < segments; ++s) {
            const double az = kTwoPi * s / segments;
            const glm::dvec3 d(std::sin(polar) * std::cos(az), std::sin(polar) * std::sin(az),
                               std::cos(polar));
            m.positions.push_back(f(c + radius * d));
            m.normals.push_back(f(d));
        }
    }
    m.positions.push_back(f(c + glm::dvec3(0, 0, radius)));
    m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    const auto pole = static_cast<unsigned>(m.positions.size() - 1);
    const auto segs = static_cast<unsigned>(segments);
    for (unsigned r = 0; r + 1 < static_cast<unsigned>(rings); ++r) {
        for (unsigned s = 0; s < segs; ++s) {
            const unsigned a = r * segs + s, b = r * segs + (s + 1) % segs;
            m.indices.insert(m.indices.end(), {a, b, b + segs, a, b + segs, a + segs});
        }
    }
    const unsigned top = (static_cast<unsigned>(rings) - 1) * segs;
    for (unsigned s = 0; s < segs; ++s)
        m.indices.insert(m.indices.end(), {top + s, top + (s + 1) % segs, pole});
    return m;
}

TestMesh floatingDisc(glm::dvec2 c, double radius, double z, double thickness, int segments) {
    TestMesh m;
    auto ring = [&](double height, glm::vec3 normal) {
        const auto first = static_cast<unsigned>(m.positions.size());
        m.positions.push_back(f({c.x, c.y, height}));
        m.normals.push_back(normal);
        for (int s = 0; s < segments; ++s) {
            const double az = kTwoPi * s / segments;
            m.positions.push_back(
                f({c.x + radius * std::cos(az), c.y + radius * std::sin(az), height}));
            m.normals.push_back(normal);
        }
        return first;
    };
    const unsigned top = ring(z, {0, 0, 1}), bottom = ring(z - thickness, {0, 0, -1});
    const auto segs = static_cast<unsigned>(segments);
    for (unsigned s = 0; s < segs; ++s) {
        const unsigned a = 1 + s, b = 1 + (s + 1) % segs;
        m.indices.insert(m.indices.end(), {top, top + a, top + b});
        m.indices.insert(m.indices.end(), {bottom, bottom + b, bottom + a});
        // The side: its own vertices with outward normals.
        const auto w = static_cast<unsigned>(m.positions.size());
        for (unsigned k : {a, b}) {
            const glm::vec3 p = m.positions[top + k];
            const glm::vec3 out = glm::normalize(glm::vec3(p.x - c.x, p.y - c.y, 0.0f));
            m.positions.push_back(p);
            m.positions.push_back(m.positions[bottom + k]);
            m.normals.push_back(out);
            m.normals.push_back(out);
        }
        m.indices.insert(m.indices.end(), {w + 1, w + 3, w + 2, w + 1, w + 2, w});
    }
    return m;
}

TestMesh openBox(const TileRect& r, double height) {
    TestMesh m;
    auto quad = [&m](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        const glm::vec3 n = glm::normalize(glm::cross(f(b - a), f(c - a)));
        const auto v = static_cast<unsigned>(m.positions.size());
        for (const glm::dvec3& p : {a, b, c, d}) {
            m.positions.push_back(f(p));
            m.normals.push_back(n);
        }
        m.indices.insert(m.indices.end(), {v, v + 1, v + 2, v, v + 2, v + 3});
    };
    const double h = height;
    quad({r.x0, r.y0, h}, {r.x1, r.y0, h}, {r.x1, r.y1, h}, {r.x0, r.y1, h});
    quad({r.x0, r.y0, 0}, {r.x1, r.y0, 0}, {r.x1, r.y0, h}, {r.x0, r.y0, h});
    quad({r.x1, r.y0, 0}, {r.x1, r.y1, 0}, {r.x1, r.y1, h}, {r.x1, r.y0, h});
    quad({r.x1, r.y1, 0}, {r.x0, r.y1, 0}, {r.x0, r.y1, h}, {r.x1, r.y1, h});
    quad({r.x0, r.y1, 0}, {r.x0, r.y0, 0}, {r.x0, r.y0, h}, {r.x0, r.y1, h});
    return m;
}

void append(TestMesh& a, const TestMesh& b) {
    const auto base = static_cast<unsigned>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    for (unsigned i : b.indices)
        a.indices.push_back(base + i);
}

TestMesh toYUp(TestMesh mesh) {
    for (glm::vec3& p : mesh.positions)
        p = {p.x, p.z, -p.y};
    for (glm::vec3& n : mesh.normals)
        n = {n.x, n.z, -n.y};
    return mesh;
}

bool writePlyBinary(const std::string& path, const TestMesh& m) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\ncomment parallax-studio mesh bake test\n"
        << "element vertex " << m.positions.size() << "\n"
        << "property float x\nproperty float y\nproperty float z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "element face " << m.indices.size() / 3 << "\n"
        << "property list uchar int vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const float v[6] = {m.positions[i].x, m.positions[i].y, m.positions[i].z,
                            m.normals[i].x,   m.normals[i].y,   m.normals[i].z};
        out.write(reinterpret_cast<const char*>(v), sizeof(v));
    }
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const std::uint8_t three = 3;
        out.write(reinterpret_cast<const char*>(&three), 1);
        const std::int32_t t[3] = {static_cast<std::int32_t>(m.indices[i]),
                                   static_cast<std::int32_t>(m.indices[i + 1]),
                                   static_cast<std::int32_t>(m.indices[i + 2])};
        out.write(reinterpret_cast<const char*>(t), sizeof(t));
    }
    return static_cast<bool>(out);
}

} // namespace px::test
