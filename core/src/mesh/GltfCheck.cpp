// glTF 2.0 (.gltf, .glb) checked before Assimp: every size a file claims is held against what is
// there, every reference resolved under the mesh's root, every index against its vertices.

#include "MeshFileChecks.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace px::mesh {

using nlohmann::json;

namespace {

// A .gltf's JSON (or a GLB's JSON chunk) larger than this is not read: nlohmann's tree costs a
// few times the text, and the refusal must stay within a few hundred MB.
constexpr std::uint64_t kMaxJsonBytes = 64ull << 20;

// Deeper JSON than this is refused: Assimp's glTF parser (RapidJSON) recurses once a level, and
// 1,000,000 nested arrays in an `extras` overflow its stack. glTF itself nests about 8 deep.
constexpr std::size_t kMaxJsonDepth = 256;
// The node hierarchy is walked recursively too (by Assimp and by the loader).
constexpr std::size_t kMaxNodeDepth = 1024;

constexpr std::uint32_t kGlbMagic = 0x46546C67u;  // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534Au; // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942u;  // "BIN\0"

// The member `key` of `object`, or an empty array: never a copy of a large member.
const json& member(const json& object, const char* key) {
    static const json none = json::array();
    if (!object.is_object())
        return none;
    const auto it = object.find(key);
    return it == object.end() ? none : *it;
}

std::uint32_t little32(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

// The deepest nesting of arrays and objects in JSON text (strings skipped).
std::size_t jsonDepth(const std::string& text) {
    std::size_t depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// a * b + c, saturating (counts a file claims may be near 2^64).
std::uint64_t mulAdd(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    constexpr std::uint64_t most = ~std::uint64_t{0};
    if (b != 0 && a > (most - c) / b)
        return most;
    return a * b + c;
}

// Where a buffer's bytes are.
struct Buffer {
    std::uint64_t length = 0; // its byteLength
    const InputFile* file = nullptr;
    std::uint64_t offset = 0;         // in `file`
    std::optional<std::string> bytes; // a decoded data: URI
};

struct View {
    std::size_t buffer = 0;
    std::uint64_t offset = 0, length = 0, stride = 0;
};

class Checker {
public:
    Checker(const InputFile& file, const MeshScope& scope) : m_file(file), m_scope(scope) {}

    Error bad(const std::string& problem) const {
        return fileError(m_scope.meshFile(), "cannot read it as a mesh: " + problem);
    }

    // A non-negative integer member (or `fallback` when absent).
    Result<std::uint64_t> count(const json& object, const char* key, const std::string& what,
                                std::optional<std::uint64_t> fallback = std::nullopt) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (fallback)
                return *fallback;
            return bad(what + " has no " + key);
        }
        if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0))
            return bad(what + "'s " + key + " is not a non-negative integer");
        return it->get<std::uint64_t>();
    }

    Status run(const json& root, std::optional<std::uint64_t> binOffset, std::uint64_t binLength,
               std::size_t maxTriangles);

private:
    Status buffers(const json& root, std::optional<std::uint64_t> binOffset,
                   std::uint64_t binLength);
    Status images(const json& root);
    Status views(const json& root);
    struct Accessor {
        std::uint64_t count = 0, components = 0;
    };
    Result<Accessor> accessor(const json& root, std::uint64_t index, const std::string& what);
    // Adds one use of an accessor, `count` elements of `components` scalars, to what Assimp
    // decodes; refused past the limit.
    Status use(std::uint64_t count, std::uint64_t components, std::uint64_t limit);
    Status nodeTree(const json& root);
    Result<std::vector<std::uint32_t>> indices(const json& accessor, const std::string& what);
    Status read(const View& view, std::uint64_t at, void* out, std::size_t bytes);

    const InputFile& m_file;
    const MeshScope& m_scope;
    std::vector<InputFile> m_opened; // external buffers
    std::vector<Buffer> m_buffers;
    std::vector<View> m_views;
    std::uint64_t m_scalars = 0; // decoded by Assimp, over every accessor use
};

// Decoded length of base64 text, or nullopt when it is not base64.
std::optional<std::string> base64(const std::string& text) {
    std::array<int, 256> value{};
    value.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i)
        value[static_cast<unsigned char>(alphabet[i])] = i;
    std::string out;
    out.reserve(text.size() / 4 * 3);
    unsigned bits = 0;
    int held = 0;
    for (const char c : text) {
        if (c == '=')
            break;
        const int v = value[static_cast<unsigned char>(c)];
        if (v < 0)
            return std::nullopt;
        bits = (bits << 6) | static_cast<unsigned>(v);
        held += 6;
        if (held >= 8) {
            held -= 8;
            out += static_cast<char>((bits >> held) & 0xff);
        }
    }
    return out;
}

Status Checker::buffers(const json& root, std::optional<std::uint64_t> binOffset,
                        std::uint64_t binLength) {
    const json& list = member(root, "buffers");
    if (!list.is_array())
        return bad("\"buffers\" is not an array");
    m_opened.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "buffer " + std::to_string(i);
        if (!list[i].is_object())
            return bad(what + " is not an object");
        Result<std::uint64_t> length = count(list[i], "byteLength", what);
        if (!length)
            return length.error();
        Buffer b;
        b.length = *length;
        const auto uri = list[i].find("uri");
        std::uint64_t available = 0;
        if (uri == list[i].end()) {
            if (i != 0 || !binOffset)
                return bad(what + " has no uri and no GLB binary chunk holds it");
            b.file = &m_file;
            b.offset = *binOffset;
            available = binLength;
        } else if (!uri->is_string()) {
            return bad(what + "'s uri is not a string");
        } else if (const std::string text = uri->get<std::string>(); text.starts_with("data:")) {
            const std::size_t comma = text.find(',');
            if (comma == std::string::npos ||
                text.substr(0, comma).find(";base64") == std::string::npos)
                return bad(what + "'s data: uri is not base64");
            b.bytes = base64(text.substr(comma + 1));
            if (!b.bytes)
                return bad(what + "'s data: uri is not valid base64");
            available = b.bytes->size();
        } else {
            Result<std::filesystem::path> path = m_scope.resolve(percentDecoded(text), what);
            if (!path)
                return path.error();
            Result<InputFile> opened = m_scope.open(*path, what);
            if (!opened)
                return opened.error();
            m_opened.push_back(std::move(*opened));
            b.file = &m_opened.back();
            available = b.file->size();
        }
        if (b.length > available)
            return bad(what + " claims " + std::to_string(b.length) + " bytes, but only " +
                       std::to_string(available) + " are there");
        m_buffers.push_back(std::move(b));
    }
    return success();
}

Status Checker::images(const json& root) {
    const json& list = member(root, "images");
    if (!list.is_array())
        return bad("\"images\" is not an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "image " + std::to_string(i);
        if (!list[i].is_object())
            return bad(what + " is not an object");
        const auto uri = list[i].find("uri");
        if (uri == list[i].end())
            continue; // in a buffer view
        if (!uri->is_string())
            return bad(what + "'s uri is not a string");
        const std::string text = uri->get<std::string>();
        if (text.starts_with("data:"))
            continue; // inside the JSON, whose size is bounded
        Result<std::filesystem::path> path = m_scope.resolve(percentDecoded(text), what);
        if (!path)
            return path.error();
        // Not read by the preview, but the mesh's: no output of the run may replace it.
        if (Status s = noteInput(path->string(), what + " of mesh " + m_scope.meshFile()); !s)
            return s;
    }
    return success();
}

Status Checker::views(const json& root) {
    const json& list = member(root, "bufferViews");
    if (!list.is_array())
        return bad("\"bufferViews\" is not an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "buffer view " + std::to_string(i);
        if (!list[i].is_object())
            return bad(what + " is not an object");
        Result<std::uint64_t> buffer = count(list[i], "buffer", what);
        Result<std::uint64_t> offset = count(list[i], "byteOffset", what, 0);
        Result<std::uint64_t> length = count(list[i], "byteLength", what);
        Result<std::uint64_t> stride = count(list[i], "byteStride", what, 0);
        for (const auto* r : {&buffer, &offset, &length, &stride}) {
            if (!*r)
                return r->error();
        }
        if (*buffer >= m_buffers.size())
            return bad(what + " names buffer " + std::to_string(*buffer) + ", which is not there");
        if (*offset > m_buffers[*buffer].length || *length > m_buffers[*buffer].length - *offset)
            return bad(what + " runs past the end of buffer " + std::to_string(*buffer));
        m_views.push_back({static_cast<std::size_t>(*buffer), *offset, *length, *stride});
    }
    return success();
}

std::uint64_t componentBytes(std::uint64_t type) {
    switch (type) {
    case 5120: // BYTE
    case 5121: // UNSIGNED_BYTE
        return 1;
    case 5122: // SHORT
    case 5123: // UNSIGNED_SHORT
        return 2;
    case 5125: // UNSIGNED_INT
    case 5126: // FLOAT
        return 4;
    default:
        return 0;
    }
}

std::uint64_t components(const std::string& type) {
    static const std::pair<const char*, std::uint64_t> table[] = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
        {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& [name, n] : table) {
        if (type == name)
            return n;
    }
    return 0;
}

// Accessor `index`'s element count and size, after checking that every element it claims lies in
// its buffer view (and its sparse part in theirs). An accessor without a view is zeros: its count
// is bounded by the data limit alone (use()).
Result<Checker::Accessor> Checker::accessor(const json& root, std::uint64_t index,
                                            const std::string& what) {
    const json& list = member(root, "accessors");
    if (!list.is_array() || index >= list.size())
        return bad(what + " names accessor " + std::to_string(index) + ", which is not there");
    const json& a = list[index];
    const std::string name = "accessor " + std::to_string(index);
    if (!a.is_object())
        return bad(name + " is not an object");
    Result<std::uint64_t> n = count(a, "count", name);
    Result<std::uint64_t> type = count(a, "componentType", name);
    if (!n || !type)
        return !n ? n.error() : type.error();
    const std::uint64_t scalars = components(a.value("type", std::string()));
    const std::uint64_t element = componentBytes(*type) * scalars;
    if (element == 0)
        return bad(name + " has an unknown type or component type");
    auto fits = [&](const json& holder, std::uint64_t elements, std::uint64_t size,
                    const std::string& part) -> Status {
        if (!holder.contains("bufferView"))
            return success(); // zeros
        Result<std::uint64_t> view = count(holder, "bufferView", part);
        Result<std::uint64_t> offset = count(holder, "byteOffset", part, 0);
        if (!view || !offset)
            return !view ? view.error() : offset.error();
        if (*view >= m_views.size())
            return bad(part + " names buffer view " + std::to_string(*view) +
                       ", which is not there");
        const View& v = m_views[*view];
        const std::uint64_t stride = v.stride > 0 ? v.stride : size;
        if (elements == 0)
            return success();
        // Overflow-safe: every quantity is bounded by a buffer's real size first.
        if (*offset > v.length || stride > v.length || elements - 1 > v.length / stride ||
            *offset + stride * (elements - 1) + size > v.length)
            return bad(part + " claims " + std::to_string(elements) + " elements of " +
                       std::to_string(size) + " bytes, past the end of buffer view " +
                       std::to_string(*view) + " (" + std::to_string(v.length) + " bytes)");
        return success();
    };
    if (Status s = fits(a, *n, element, name); !s)
        return s.error();
    if (const auto sparse = a.find("sparse"); sparse != a.end() && sparse->is_object()) {
        Result<std::uint64_t> k = count(*sparse, "count", name + " (sparse)");
        if (!k)
            return k.error();
        if (*k > *n)
            return bad(name + " has more sparse elements than elements");
        const json& indices = member(*sparse, "indices");
        const std::uint64_t indexBytes = componentBytes(indices.value("componentType", 0));
        if (indexBytes == 0 || !indices.contains("bufferView") ||
            !member(*sparse, "values").contains("bufferView"))
            return bad(name + "'s sparse part is incomplete");
        if (Status s = fits(indices, *k, indexBytes, name + "'s sparse indices"); !s)
            return s.error();
        if (Status s = fits(member(*sparse, "values"), *k, element, name + "'s sparse values"); !s)
            return s.error();
    }
    return Accessor{*n, scalars};
}

Status Checker::read(const View& view, std::uint64_t at, void* out, std::size_t bytes) {
    const Buffer& b = m_buffers[view.buffer];
    if (b.bytes) {
        std::memcpy(out, b.bytes->data() + view.offset + at, bytes);
        return success();
    }
    return b.file->readAt(b.offset + view.offset + at, out, bytes);
}

// An index accessor's values (its size already checked).
Result<std::vector<std::uint32_t>> Checker::indices(const json& a, const std::string& what) {
    const std::uint64_t n = a.at("count").get<std::uint64_t>();
    const std::uint64_t type = a.at("componentType").get<std::uint64_t>();
    const std::uint64_t size = componentBytes(type);
    if (a.value("type", std::string()) != "SCALAR" || type == 5120 || type == 5122 || type == 5126)
        return bad(what + "'s indices are not unsigned integers");
    std::vector<std::uint32_t> values(static_cast<std::size_t>(n), 0);
    auto load = [&](const json& holder, std::vector<std::uint32_t>& into,
                    std::uint64_t elementSize) -> Status {
        if (!holder.contains("bufferView"))
            return success();
        const View& v = m_views[holder.at("bufferView").get<std::size_t>()];
        const std::uint64_t offset = holder.value("byteOffset", std::uint64_t{0});
        const std::uint64_t stride = v.stride > 0 ? v.stride : elementSize;
        std::vector<unsigned char> bytes(
            static_cast<std::size_t>(into.empty() ? 0 : stride * (into.size() - 1) + elementSize));
        if (!bytes.empty()) {
            if (Status s = read(v, offset, bytes.data(), bytes.size()); !s)
                return s;
        }
        for (std::size_t i = 0; i < into.size(); ++i) {
            const unsigned char* p = bytes.data() + i * stride;
            into[i] = elementSize == 1   ? p[0]
                      : elementSize == 2 ? static_cast<std::uint32_t>(p[0] | p[1] << 8)
                                         : little32(p);
        }
        return success();
    };
    if (Status s = load(a, values, size); !s)
        return s.error();
    if (const auto sparse = a.find("sparse"); sparse != a.end() && sparse->is_object()) {
        const json& at = member(*sparse, "indices");
        std::vector<std::uint32_t> where(sparse->at("count").get<std::size_t>()),
            replaced(where.size());
        if (Status s = load(at, where, componentBytes(at.at("componentType").get<std::uint64_t>()));
            !s)
            return s.error();
        if (Status s = load(member(*sparse, "values"), replaced, size); !s)
            return s.error();
        for (std::size_t k = 0; k < where.size(); ++k) {
            if (where[k] >= values.size())
                return bad(what + "'s sparse index " + std::to_string(where[k]) +
                           " is past the end of its " + std::to_string(values.size()) + " indices");
            values[where[k]] = replaced[k];
        }
    }
    return values;
}

// The faces Assimp makes of `corners` corners in glTF primitive mode `mode` (0 to 6).
std::uint64_t facesOf(std::uint64_t mode, std::uint64_t corners) {
    switch (mode) {
    case 0: // POINTS
    case 2: // LINE_LOOP
        return corners;
    case 1: // LINES
        return corners / 2;
    case 3: // LINE_STRIP
        return corners > 1 ? corners - 1 : 0;
    case 4: // TRIANGLES
        return corners / 3;
    default: // TRIANGLE_STRIP, TRIANGLE_FAN
        return corners > 2 ? corners - 2 : 0;
    }
}

Status Checker::use(std::uint64_t count, std::uint64_t components, std::uint64_t limit) {
    m_scalars = mulAdd(count, components, m_scalars);
    if (m_scalars > limit)
        return fileError(m_scope.meshFile(),
                         "its accessors hold more than " + std::to_string(limit) +
                             " values (meshes, morph targets, skins and animations together), "
                             "more than a mesh within the preview's triangle limit can use");
    return success();
}

// Nodes form trees (glTF 2.0 §3.5.3): each node the child of at most one, no cycle, no deeper than
// kMaxNodeDepth. A cycle would recurse without end, a node shared by many parents multiply.
Status Checker::nodeTree(const json& root) {
    const json& nodes = member(root, "nodes");
    if (!nodes.is_array())
        return bad("\"nodes\" is not an array");
    constexpr std::size_t kNone = ~std::size_t{0};
    std::vector<std::size_t> parent(nodes.size(), kNone);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const json& children = member(nodes[i], "children");
        if (!children.is_array())
            return bad("node " + std::to_string(i) + "'s children are not an array");
        for (const json& child : children) {
            if (!child.is_number_unsigned() || child.get<std::uint64_t>() >= nodes.size())
                return bad("node " + std::to_string(i) + " has a child that is not a node");
            const auto c = child.get<std::size_t>();
            if (parent[c] != kNone || c == i)
                return bad("node " + std::to_string(c) +
                           " is the child of more than one node (or of itself): the nodes do not "
                           "form a tree");
            parent[c] = i;
        }
    }
    // Depth of each node, each computed once (0: not yet); a walk longer than the node count
    // has met a cycle.
    std::vector<std::size_t> depth(nodes.size(), 0);
    std::vector<std::size_t> chain;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        chain.clear();
        std::size_t at = i;
        while (at != kNone && depth[at] == 0) {
            chain.push_back(at);
            if (chain.size() > nodes.size())
                return bad("its nodes form a cycle (node " + std::to_string(i) +
                           " is its own ancestor)");
            at = parent[at];
        }
        std::size_t d = at == kNone ? 0 : depth[at];
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            depth[*it] = ++d;
            if (d > kMaxNodeDepth)
                return bad("its node hierarchy is more than " + std::to_string(kMaxNodeDepth) +
                           " levels deep");
        }
    }
    return success();
}

Status Checker::run(const json& root, std::optional<std::uint64_t> binOffset,
                    std::uint64_t binLength, std::size_t maxTriangles) {
    if (!root.is_object())
        return bad("the glTF document is not a JSON object");
    const json asset = root.value("asset", json::object());
    const std::string version = asset.is_object() ? asset.value("version", std::string()) : "";
    if (!version.starts_with("2."))
        return bad("it is glTF " + (version.empty() ? std::string("of no version") : version) +
                   "; the preview reads glTF 2.0");
    if (Status s = buffers(root, binOffset, binLength); !s)
        return s;
    if (Status s = images(root); !s)
        return s;
    if (Status s = views(root); !s)
        return s;
    if (Status s = nodeTree(root); !s)
        return s;

    // Assimp decodes every accessor each time it is used: a primitive's attributes and indices,
    // each morph target (at the primitive's vertex count), a skinned mesh again for every node
    // drawing it, each animation channel's input and output. Summed, no more values than a mesh
    // within the triangle limit can use: kScalarsPerCorner for each of its three corners a
    // triangle (position, normal, tangent, two uv sets, a colour, joints and weights, with room
    // for targets and animation).
    constexpr std::uint64_t kScalarsPerCorner = 32;
    const std::uint64_t limit =
        mulAdd(3 * std::max<std::uint64_t>(maxTriangles, 1), kScalarsPerCorner, 0);
    const json& meshes = member(root, "meshes");
    if (!meshes.is_array())
        return bad("\"meshes\" is not an array");
    std::vector<std::uint64_t> instances(meshes.size(), 0), meshScalars(meshes.size(), 0);
    const json& nodes = member(root, "nodes");
    for (const json& node : nodes) {
        if (node.is_object() && node.contains("mesh") && node["mesh"].is_number_unsigned() &&
            node["mesh"].get<std::uint64_t>() < meshes.size())
            ++instances[node["mesh"].get<std::size_t>()];
    }
    // Triangles as the loader keeps them (times the nodes drawing each mesh); points and lines
    // as Assimp builds them (one face each) before they are sorted out.
    std::uint64_t triangles = 0, otherFaces = 0;
    const auto tooMany = [&](std::uint64_t tris, std::uint64_t others) -> Status {
        if (others == 0 && tris > maxTriangles)
            return tooManyTriangles(m_scope.meshFile(), static_cast<std::size_t>(tris),
                                    maxTriangles);
        if (tris + others > maxTriangles)
            return fileError(m_scope.meshFile(),
                             std::to_string(tris + others) +
                                 " points, lines and triangles, more than the preview's limit "
                                 "of " +
                                 std::to_string(maxTriangles));
        return success();
    };
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const json& primitives = member(meshes[m], "primitives");
        if (!primitives.is_array())
            return bad("mesh " + std::to_string(m) + "'s primitives are not an array");
        const std::uint64_t before = m_scalars;
        std::uint64_t inMesh = 0;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const std::string what =
                "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            const json& primitive = primitives[p];
            if (!member(primitive, "attributes").is_object())
                return bad(what + " has no attributes");
            Result<std::uint64_t> mode = count(primitive, "mode", what, 4);
            if (!mode)
                return mode.error();
            if (*mode > 6)
                return bad(what + " has mode " + std::to_string(*mode) +
                           ", which glTF does not define");
            std::uint64_t vertices = 0;
            for (const auto& [name, index] : primitive.at("attributes").items()) {
                if (!index.is_number_unsigned())
                    return bad(what + "'s attribute " + name + " is not an accessor index");
                Result<Accessor> a =
                    accessor(root, index.get<std::uint64_t>(), what + "'s " + name);
                if (!a)
                    return a.error();
                if (Status s = use(a->count, a->components, limit); !s)
                    return s;
                if (name == "POSITION")
                    vertices = a->count;
            }
            const json& targets = member(primitive, "targets");
            if (!targets.is_array())
                return bad(what + "'s morph targets are not an array");
            for (std::size_t t = 0; t < targets.size(); ++t) {
                if (!targets[t].is_object())
                    return bad(what + "'s morph target " + std::to_string(t) + " is not an object");
                for (const auto& [name, index] : targets[t].items()) {
                    const std::string part =
                        what + "'s morph target " + std::to_string(t) + " " + name;
                    if (!index.is_number_unsigned())
                        return bad(part + " is not an accessor index");
                    Result<Accessor> a = accessor(root, index.get<std::uint64_t>(), part);
                    if (!a)
                        return a.error();
                    if (Status s = use(std::max(a->count, vertices), a->components, limit); !s)
                        return s;
                }
            }
            std::uint64_t corners = vertices;
            std::optional<std::uint64_t> indexAccessor;
            if (primitive.contains("indices")) {
                Result<std::uint64_t> n = count(primitive, "indices", what);
                if (!n)
                    return n.error();
                Result<Accessor> k = accessor(root, *n, what + "'s indices");
                if (!k)
                    return k.error();
                if (Status s = use(k->count, k->components, limit); !s)
                    return s;
                corners = k->count;
                indexAccessor = *n;
            }
            const std::uint64_t faces = facesOf(*mode, corners);
            (*mode >= 4 ? inMesh : otherFaces) += faces;
            if (Status s = tooMany(*mode >= 4 ? faces : 0, *mode >= 4 ? 0 : faces); !s)
                return s;
            if (indexAccessor) {
                // As many as the limit allows at most: read and check every index.
                Result<std::vector<std::uint32_t>> values =
                    indices(member(root, "accessors").at(*indexAccessor), what);
                if (!values)
                    return values.error();
                for (std::size_t i = 0; i < values->size(); ++i) {
                    if ((*values)[i] >= vertices)
                        return fileError(m_scope.meshFile(),
                                         what + ": index " + std::to_string((*values)[i]) +
                                             " (at position " + std::to_string(i) +
                                             ") is past the end of its " +
                                             std::to_string(vertices) + " vertices");
                }
            }
        }
        meshScalars[m] = m_scalars - before;
        triangles = mulAdd(inMesh, std::max<std::uint64_t>(instances[m], 1), triangles);
        if (Status s = tooMany(triangles, otherFaces); !s)
            return s;
    }

    // A skinned mesh is copied for each node drawing it, with a bone per joint.
    const json& skins = member(root, "skins");
    if (!skins.is_array())
        return bad("\"skins\" is not an array");
    for (std::size_t i = 0; i < skins.size(); ++i) {
        const std::string what = "skin " + std::to_string(i);
        if (!skins[i].is_object())
            return bad(what + " is not an object");
        if (skins[i].contains("inverseBindMatrices")) {
            Result<std::uint64_t> n = count(skins[i], "inverseBindMatrices", what);
            if (!n)
                return n.error();
            Result<Accessor> a = accessor(root, *n, what + "'s inverse bind matrices");
            if (!a)
                return a.error();
            if (Status s = use(a->count, a->components, limit); !s)
                return s;
        }
    }
    for (const json& node : nodes) {
        if (!node.is_object() || !node.contains("skin") || !node.contains("mesh") ||
            !node["mesh"].is_number_unsigned() ||
            node["mesh"].get<std::uint64_t>() >= meshes.size())
            continue;
        if (Status s = use(meshScalars[node["mesh"].get<std::size_t>()], 1, limit); !s)
            return s;
    }

    // Each channel's sampler is decoded for that channel: its input (times) and output (values).
    const json& animations = member(root, "animations");
    if (!animations.is_array())
        return bad("\"animations\" is not an array");
    for (std::size_t i = 0; i < animations.size(); ++i) {
        const std::string what = "animation " + std::to_string(i);
        const json& samplers = member(animations[i], "samplers");
        const json& channels = member(animations[i], "channels");
        if (!samplers.is_array() || !channels.is_array())
            return bad(what + "'s samplers or channels are not an array");
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const std::string channel = what + " channel " + std::to_string(c);
            if (!channels[c].is_object())
                return bad(channel + " is not an object");
            Result<std::uint64_t> s = count(channels[c], "sampler", channel);
            if (!s)
                return s.error();
            if (*s >= samplers.size() || !samplers[*s].is_object())
                return bad(channel + " names sampler " + std::to_string(*s) +
                           ", which is not there");
            for (const char* key : {"input", "output"}) {
                const std::string part = what + " sampler " + std::to_string(*s) + "'s " + key;
                Result<std::uint64_t> n = count(samplers[*s], key, part);
                if (!n)
                    return n.error();
                Result<Accessor> a = accessor(root, *n, part);
                if (!a)
                    return a.error();
                if (Status u = use(a->count, a->components, limit); !u)
                    return u;
            }
        }
    }
    return success();
}

Result<json> parseJson(const std::string& text, const MeshScope& scope) {
    if (const std::size_t depth = jsonDepth(text); depth > kMaxJsonDepth)
        return fileError(scope.meshFile(), "cannot read it as a mesh: its JSON nests " +
                                               std::to_string(depth) + " levels deep, more than " +
                                               "the " + std::to_string(kMaxJsonDepth) +
                                               " the preview reads");
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        return fileError(scope.meshFile(),
                         std::string("cannot read it as a mesh: its JSON does not parse (") +
                             e.what() + ")");
    }
}

Status checkGltfDocument(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles);

} // namespace

Error tooManyTriangles(const std::string& file, std::size_t triangles, std::size_t limit) {
    return fileError(file, std::to_string(triangles) +
                               " triangles, more than the preview's limit of " +
                               std::to_string(limit));
}

Status checkGltf(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles) {
    try {
        return checkGltfDocument(file, scope, maxTriangles);
    } catch (const json::exception& e) { // a member of an unexpected type
        return fileError(scope.meshFile(),
                         std::string("cannot read it as a mesh: it is not a glTF document (") +
                             e.what() + ")");
    }
}

namespace {

Status checkGltfDocument(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles) {
    Checker checker(file, scope);
    unsigned char header[20] = {};
    const bool binary =
        file.size() >= 12 && file.readAt(0, header, 4) && little32(header) == kGlbMagic;
    if (!binary) {
        if (file.size() > kMaxJsonBytes)
            return checker.bad("its JSON is " + std::to_string(file.size()) +
                               " bytes, more than the " + std::to_string(kMaxJsonBytes) +
                               " the preview reads");
        Result<std::string> text = file.readAll(kMaxJsonBytes);
        if (!text)
            return text.error();
        Result<json> root = parseJson(*text, scope);
        if (!root)
            return root.error();
        return checker.run(*root, std::nullopt, 0, maxTriangles);
    }
    if (file.size() < 20 || !file.readAt(0, header, 20))
        return checker.bad("its GLB header is cut short");
    const std::uint32_t version = little32(header + 4), length = little32(header + 8);
    if (version != 2)
        return checker.bad("its GLB header says version " + std::to_string(version) +
                           "; the preview reads glTF 2.0");
    if (length != file.size())
        return checker.bad("its GLB header claims " + std::to_string(length) +
                           " bytes, but the file has " + std::to_string(file.size()));
    const std::uint64_t jsonLength = little32(header + 12);
    if (little32(header + 16) != kJsonChunk || jsonLength > file.size() - 20)
        return checker.bad("its JSON chunk claims " + std::to_string(jsonLength) +
                           " bytes, past the end of the " + std::to_string(file.size()) +
                           "-byte file");
    if (jsonLength > kMaxJsonBytes)
        return checker.bad("its JSON chunk is " + std::to_string(jsonLength) +
                           " bytes, more than the " + std::to_string(kMaxJsonBytes) +
                           " the preview reads");
    std::string text(static_cast<std::size_t>(jsonLength), '\0');
    if (Status s = file.readAt(20, text.data(), text.size()); !s)
        return s;
    std::optional<std::uint64_t> binOffset;
    std::uint64_t binLength = 0;
    const std::uint64_t next = 20 + (jsonLength + 3) / 4 * 4;
    if (next + 8 <= file.size()) {
        unsigned char chunk[8];
        if (Status s = file.readAt(next, chunk, 8); !s)
            return s;
        binLength = little32(chunk);
        if (little32(chunk + 4) == kBinChunk) {
            if (binLength > file.size() - next - 8)
                return checker.bad("its binary chunk claims " + std::to_string(binLength) +
                                   " bytes, past the end of the " + std::to_string(file.size()) +
                                   "-byte file");
            binOffset = next + 8;
        }
    }
    Result<json> root = parseJson(text, scope);
    if (!root)
        return root.error();
    return checker.run(*root, binOffset, binLength, maxTriangles);
}

} // namespace

} // namespace px::mesh
