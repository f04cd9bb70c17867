#include "mesh/MeshFileChecks.h"
#include "mesh/MeshScope.h"
#include "meshbake/MeshSizeCheck.h"
#include "parallax/io/FileExtension.h"
#include "parallax/io/Inputs.h"
#include "parallax/meshbake/BakeMesh.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace px {

namespace {

class ProgressRelay : public Assimp::ProgressHandler {
public:
    ProgressRelay(std::function<bool(float)> report, bool& cancelled)
        : m_report(std::move(report)), m_cancelled(cancelled) {}
    bool Update(float fraction) override {
        if (m_report && fraction >= 0.0f && !m_report(std::min(fraction, 1.0f)))
            m_cancelled = true;
        return !m_cancelled;
    }

private:
    std::function<bool(float)> m_report;
    bool& m_cancelled;
};

struct Instance {
    const aiMesh* mesh;
    unsigned index;
    glm::mat4 model;
};

void collectInstances(const aiScene& scene, const aiNode& node, const glm::mat4& parent,
                      std::vector<Instance>& out) {
    // aiMatrix4x4 is row-major: read as column-major it is the transpose.
    const glm::mat4 model = parent * glm::transpose(glm::make_mat4(&node.mTransformation.a1));
    for (unsigned i = 0; i < node.mNumMeshes; ++i)
        out.push_back({scene.mMeshes[node.mMeshes[i]], node.mMeshes[i], model});
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        collectInstances(scene, *node.mChildren[c], model, out);
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The checks the format allows before Assimp allocates anything.
Status checkBeforeReading(const InputFile& file, const mesh::MeshScope& scope,
                          std::size_t maxTriangles) {
    const std::string ext = lowerExtension(file.path());
    Status checked = success();
    if (ext == ".obj")
        checked = mesh::checkObj(file, scope, maxTriangles);
    else if (ext == ".gltf" || ext == ".glb")
        checked = mesh::checkGltf(file, scope, maxTriangles);
    else if (ext == ".ply")
        checked = meshbake::checkPly(file, maxTriangles);
    else if (ext == ".stl")
        checked = meshbake::checkStl(file, maxTriangles);
    if (checked)
        return checked;
    // The preview's checks speak of the preview's limit; here it is the bake's.
    std::string message = checked.error().message;
    const std::string preview = "the preview's limit";
    if (const std::size_t at = message.find(preview); at != std::string::npos)
        message.replace(at, preview.size(), "the bake's limit");
    return Error{message, checked.error().kind, checked.error().file};
}

// Zero area relative to the edges, independent of the mesh's units.
bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    return !(glm::length(glm::cross(e1, e2)) > 1e-7f * glm::length(e1) * glm::length(e2));
}

} // namespace

bool isBakeMeshFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".gltf" || ext == ".glb" ||
           ext == ".fbx";
}

BakeMesh makeBakeMesh(const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals, std::vector<unsigned> indices,
                      std::string name) {
    BakeMesh out;
    out.file = std::move(name);
    out.positions.reserve(3 * positions.size() + 1);
    for (const glm::vec3& p : positions)
        out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
    out.positions.push_back(0.0f);
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = glm::length(n) > 0.0f ? glm::normalize(n) : n;
        out.normals.insert(out.normals.end(), {u.x, u.y, u.z});
    }
    out.indices = std::move(indices);
    out.lo = glm::vec3(INFINITY);
    out.hi = glm::vec3(-INFINITY);
    for (unsigned i : out.indices) {
        out.lo = glm::min(out.lo, positions[i]);
        out.hi = glm::max(out.hi, positions[i]);
    }
    return out;
}

Result<BakeMesh> loadBakeMesh(const std::string& path, const BakeMeshLoadOptions& options) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return fileError(path, "no such file");
    if (std::filesystem::is_directory(path, ec))
        return fileError(path, "is a folder, not a mesh");
    if (!isBakeMeshFile(path))
        return fileError(path, "not a mesh file (the mesh bake reads .obj, .ply, .stl, .gltf, "
                               ".glb and .fbx)");
    Result<InputFile> file = InputFile::open(path, "--mesh");
    if (!file)
        return file.error();
    Result<mesh::MeshScope> scope = mesh::MeshScope::make(path, options.root);
    if (!scope)
        return scope.error();
    if (Status s = checkBeforeReading(*file, *scope, options.maxTriangles); !s)
        return s.error();

    bool cancelled = false;
    Assimp::Importer importer;
    auto* io = new mesh::ScopedIoSystem(*scope); // the importer owns and deletes it
    importer.SetIOHandler(io);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetProgressHandler(new ProgressRelay(options.progress, cancelled));
    // Polygons cut into triangles; nothing else: the baker needs no joined vertices (normals are
    // the file's or the faces'), and joining 10M corners costs seconds.
    const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType;
    const aiScene* scene = nullptr;
    try {
        scene = importer.ReadFile(path, flags);
    } catch (const std::exception& e) {
        return fileError(path, std::string("cannot read it as a mesh: ") + e.what());
    }
    if (cancelled)
        return Error{path + ": loading cancelled", ErrorKind::Cancelled, path};
    if (!io->refusal().empty())
        return fileError(path, "cannot read it as a mesh: " + io->refusal());
    if (scene == nullptr) {
        const std::string why = importer.GetErrorString();
        return fileError(path,
                         "cannot read it as a mesh: " + (why.empty() ? "unknown error" : why));
    }

    std::vector<Instance> instances;
    if (scene->mRootNode != nullptr)
        collectInstances(*scene, *scene->mRootNode, glm::mat4(1.0f), instances);
    std::size_t triangles = 0, vertices = 0;
    bool allNormals = true;
    for (const Instance& instance : instances) {
        for (unsigned f = 0; f < instance.mesh->mNumFaces; ++f)
            triangles += instance.mesh->mFaces[f].mNumIndices == 3;
        vertices += instance.mesh->mNumVertices;
        allNormals = allNormals && instance.mesh->HasNormals();
    }
    if (triangles == 0)
        return fileError(path, "has no triangles");
    if (triangles > options.maxTriangles)
        return meshbake::tooManyTriangles(path, triangles, options.maxTriangles);

    BakeMesh out;
    out.file = path;
    out.positions.reserve(3 * vertices + 1);
    if (allNormals)
        out.normals.reserve(3 * vertices);
    else
        out.notes.push_back(path + ": not every part has vertex normals: face normals are baked");
    out.indices.reserve(3 * triangles);
    // Y-up files turn so that +Y becomes +Z and -Z the image's top: (x, y, z) -> (x, -z, y).
    const glm::mat3 up = options.up == MeshUp::Y ? glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1),
                                                             glm::vec3(0, -1, 0))
                                                 : glm::mat3(1.0f);
    out.lo = glm::vec3(INFINITY);
    out.hi = glm::vec3(-INFINITY);
    for (const Instance& instance : instances) {
        const aiMesh& mesh = *instance.mesh;
        const std::string name = mesh.mName.length > 0
                                     ? "mesh \"" + std::string(mesh.mName.C_Str()) + "\""
                                     : "mesh " + std::to_string(instance.index);
        const glm::mat4 model = glm::mat4(up) * instance.model;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
        const bool mirrors = glm::determinant(glm::mat3(model)) < 0.0f;
        const auto base = static_cast<unsigned>(out.positions.size() / 3);
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            const aiVector3D& v = mesh.mVertices[i];
            const glm::vec3 p = glm::vec3(model * glm::vec4(v.x, v.y, v.z, 1.0f));
            if (!finite(p))
                return fileError(path, "vertex " + std::to_string(i) + " of " + name +
                                           " has a non-finite position");
            out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
            if (allNormals) {
                const aiVector3D& m = mesh.mNormals[i];
                glm::vec3 n = normalMatrix * glm::vec3(m.x, m.y, m.z);
                if (!finite(n))
                    return fileError(path, "vertex " + std::to_string(i) + " of " + name +
                                               " has a non-finite normal");
                // A zero normal stays zero: the hit falls back to its face normal.
                if (glm::length(n) > 0.0f)
                    n = glm::normalize(n);
                out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
            }
        }
        auto at = [&out](unsigned k) {
            return glm::vec3(out.positions[3 * k], out.positions[3 * k + 1],
                             out.positions[3 * k + 2]);
        };
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3)
                continue;
            const unsigned a = base + face.mIndices[0], b = base + face.mIndices[mirrors ? 2 : 1],
                           c = base + face.mIndices[mirrors ? 1 : 2];
            if (face.mIndices[0] >= mesh.mNumVertices || face.mIndices[1] >= mesh.mNumVertices ||
                face.mIndices[2] >= mesh.mNumVertices)
                return fileError(path, "face " + std::to_string(f) + " of " + name +
                                           " refers to a vertex it does not have");
            const glm::vec3 pa = at(a), pb = at(b), pc = at(c);
            if (degenerate(pa, pb, pc)) {
                ++out.droppedTriangles;
                continue;
            }
            out.lo = glm::min(glm::min(out.lo, pa), glm::min(pb, pc));
            out.hi = glm::max(glm::max(out.hi, pa), glm::max(pb, pc));
            out.indices.insert(out.indices.end(), {a, b, c});
        }
    }
    out.positions.push_back(0.0f); // Embree's 16-byte read of the last vertex
    if (out.indices.empty())
        return fileError(path, "every one of its " + std::to_string(triangles) +
                                   " triangles has zero area");
    if (out.droppedTriangles > 0)
        out.notes.push_back(path + ": dropped " + std::to_string(out.droppedTriangles) + " of " +
                            std::to_string(triangles) + " triangles with zero area");
    return out;
}

} // namespace px
