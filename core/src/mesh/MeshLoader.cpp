#include "parallax/mesh/MeshLoader.h"

#include "MeshFileChecks.h"
#include "parallax/io/FileExtension.h"
#include "parallax/io/Inputs.h"
#include "parallax/mesh/TangentFrames.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <optional>
#include <sstream>

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

bool finite(const aiVector3D& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string text(const aiVector3D& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

glm::vec3 vec(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}

// A mesh where a node draws it: the nodes' transforms multiplied down from the root.
struct Instance {
    const aiMesh* mesh;
    unsigned index;  // in the scene
    glm::mat4 model; // file units, the scene's frame
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

// Zero area in position or in uv (relative to the edges, so independent of the mesh's units):
// such a triangle has no tangent frame and covers nothing.
bool degenerate(const MeshVertex& a, const MeshVertex& b, const MeshVertex& c) {
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float area = glm::length(glm::cross(e1, e2));
    const float uvArea = std::abs(d1.x * d2.y - d2.x * d1.y);
    return !(area > 1e-6f * glm::length(e1) * glm::length(e2)) ||
           !(uvArea > 1e-6f * glm::length(d1) * glm::length(d2));
}

// Area-weighted normals from the kept triangles, for files without normals (or with zero ones).
void fillMissingNormals(MeshData& mesh) {
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::vec3& a = mesh.vertices[mesh.indices[i]].position;
        const glm::vec3 n = glm::cross(mesh.vertices[mesh.indices[i + 1]].position - a,
                                       mesh.vertices[mesh.indices[i + 2]].position - a);
        for (int k = 0; k < 3; ++k)
            sums[mesh.indices[i + k]] += n;
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        MeshVertex& out = mesh.vertices[v];
        if (glm::length(out.normal) > 0.0f)
            out.normal = glm::normalize(out.normal);
        else if (glm::length(sums[v]) > 0.0f)
            out.normal = glm::normalize(sums[v]);
    }
}

// Centre of the bounding box to the origin, farthest used vertex at distance 1.
float fitIntoUnitSphere(MeshData& mesh) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (unsigned i : mesh.indices) {
        lo = glm::min(lo, mesh.vertices[i].position);
        hi = glm::max(hi, mesh.vertices[i].position);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (unsigned i : mesh.indices)
        radius = std::max(radius, glm::length(mesh.vertices[i].position - centre));
    const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
    for (MeshVertex& v : mesh.vertices)
        v.position = (v.position - centre) * scale;
    return scale;
}

// Records every texture the scene's materials name as an input of the run, as Assimp read the
// names (an MTL's "map_Kd my tex.png" is "my tex.png", whatever its line ends): no output may
// replace one. Relative names are tried against the mesh's folder and each material library's.
Status noteTextures(const aiScene& scene, const mesh::MeshScope& scope,
                    const mesh::ScopedIoSystem& io) {
    std::vector<std::filesystem::path> bases{{}};
    for (const std::filesystem::path& opened : io.opened()) {
        if (lowerExtension(opened.string()) == ".mtl")
            bases.push_back(opened.parent_path());
    }
    for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
        const aiMaterial& material = *scene.mMaterials[m];
        for (int type = aiTextureType_NONE; type <= AI_TEXTURE_TYPE_MAX; ++type) {
            const auto t = static_cast<aiTextureType>(type);
            for (unsigned i = 0; i < material.GetTextureCount(t); ++i) {
                aiString name;
                if (material.GetTexture(t, i, &name) != aiReturn_SUCCESS || name.length == 0 ||
                    name.data[0] == '*' || std::string_view(name.C_Str()).starts_with("data:"))
                    continue; // embedded
                const std::string text = name.C_Str();
                // Refused only when no reading of the name lies inside the root.
                std::optional<Error> outside;
                bool inside = false;
                for (const std::string& reference : {text, mesh::percentDecoded(text)}) {
                    for (const std::filesystem::path& base : bases) {
                        Result<std::filesystem::path> path =
                            scope.resolve(reference, "texture " + reference, base);
                        if (!path) {
                            outside = outside.value_or(path.error());
                            continue;
                        }
                        inside = true;
                        if (Status s =
                                noteInput(path->string(), "a texture of mesh " + scope.meshFile());
                            !s)
                            return s;
                    }
                }
                if (!inside && outside)
                    return *outside;
            }
        }
    }
    return success();
}

} // namespace

bool isMeshFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

std::string LoadedMesh::summary() const {
    std::ostringstream out;
    out << file << ": " << triangles << " triangles, uv set " << uvSet << " of " << uvSets << ", ";
    if (fileTangents)
        out << "the file's tangents";
    else
        out << "tangents generated (MikkTSpace-compatible)";
    if (splitVertices > 0)
        out << ", " << splitVertices << " vertices split where the uv is mirrored";
    return out.str();
}

Result<LoadedMesh> loadMesh(const std::string& path, const MeshLoadOptions& options) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return fileError(path, "no such file");
    if (std::filesystem::is_directory(path, ec))
        return fileError(path, "is a folder, not a mesh");
    if (!isMeshFile(path))
        return fileError(path, "not a mesh file (the preview reads .obj, .gltf and .glb)");
    // Before Assimp allocates anything: sizes against the file and the triangle limit, references
    // under the mesh's root (MeshFileChecks.h).
    Result<InputFile> file = InputFile::open(path);
    if (!file)
        return file.error();
    Result<mesh::MeshScope> scope = mesh::MeshScope::make(path, options.root);
    if (!scope)
        return scope.error();
    const Status checked = lowerExtension(path) == ".obj"
                               ? mesh::checkObj(*file, *scope, options.maxTriangles)
                               : mesh::checkGltf(*file, *scope, options.maxTriangles);
    if (!checked)
        return checked.error();

    bool cancelled = false;
    Assimp::Importer importer;
    // Every file Assimp opens goes through the scope (the importer owns and deletes it).
    auto* io = new mesh::ScopedIoSystem(*scope);
    importer.SetIOHandler(io);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // The importer owns and deletes its progress handler.
    importer.SetProgressHandler(new ProgressRelay(options.progress, cancelled));
    // Polygons cut into triangles, identical corners shared (OBJ lists every face's corners
    // apart): MikkTSpace welds them too. Normals and frames are ours. Node transforms are applied
    // below, not by Assimp's PreTransformVertices: it turns tangents by the normals' inverse
    // transpose, 49 degrees off under a (1.6, 1, 0.6) scale, where a tangent, a direction along
    // the surface, goes by the transform itself.
    const unsigned flags =
        aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType;
    const aiScene* scene = nullptr;
    try {
        scene = importer.ReadFile(path, flags);
    } catch (const std::exception& e) {
        return fileError(path, std::string("cannot read it as a mesh: ") + e.what());
    }
    if (cancelled)
        return Error{path + ": loading cancelled", ErrorKind::Cancelled, path};
    if (!io->refusal().empty()) // Assimp may carry on without a file it was refused
        return fileError(path, "cannot read it as a mesh: " + io->refusal());
    if (scene == nullptr) {
        std::string why = importer.GetErrorString();
        if (!io->refusal().empty())
            why += (why.empty() ? "" : ": ") + io->refusal();
        return fileError(path,
                         "cannot read it as a mesh: " + (why.empty() ? "unknown error" : why));
    }
    if (Status s = noteTextures(*scene, *scope, *io); !s)
        return s.error();

    LoadedMesh out;
    out.file = path;
    std::vector<Instance> instances;
    if (scene->mRootNode != nullptr)
        collectInstances(*scene, *scene->mRootNode, glm::mat4(1.0f), instances);
    std::size_t triangles = 0;
    for (const Instance& instance : instances) {
        const aiMesh& mesh = *instance.mesh;
        out.uvSets = std::max(out.uvSets, static_cast<int>(mesh.GetNumUVChannels()));
        for (unsigned f = 0; f < mesh.mNumFaces; ++f)
            triangles += mesh.mFaces[f].mNumIndices == 3;
    }
    if (triangles == 0)
        return fileError(path, "has no triangles");
    if (triangles > options.maxTriangles)
        return fileError(path, std::to_string(triangles) +
                                   " triangles, more than the preview's limit of " +
                                   std::to_string(options.maxTriangles));
    if (out.uvSets == 0)
        return fileError(path, "has no texture coordinates (uv); parallax mapping needs them");
    if (options.uvSet < 0 || options.uvSet >= out.uvSets)
        return fileError(path, "has " + std::to_string(out.uvSets) + " uv set" +
                                   (out.uvSets == 1 ? "" : "s") + "; uv set " +
                                   std::to_string(options.uvSet) + " does not exist");

    const auto set = static_cast<unsigned>(options.uvSet);
    out.uvSet = options.uvSet;
    out.fileTangents = true;
    for (const Instance& instance : instances)
        out.fileTangents = out.fileTangents && instance.mesh->HasTangentsAndBitangents() &&
                           instance.mesh->HasNormals();
    MeshData& data = out.mesh;
    data.vertices.reserve(triangles); // about as many vertices as triangles on a closed mesh
    data.indices.reserve(3 * triangles);
    for (const Instance& instance : instances) {
        const aiMesh& mesh = *instance.mesh;
        const std::string name = mesh.mName.length > 0
                                     ? "mesh \"" + std::string(mesh.mName.C_Str()) + "\""
                                     : "mesh " + std::to_string(instance.index);
        // Positions and tangents go by the transform, normals by its inverse transpose; a
        // mirroring transform turns the triangles over, so their corners swap to stay
        // counter-clockwise (as glTF asks).
        const glm::mat3 linear(instance.model);
        const glm::mat3 normals = glm::transpose(glm::inverse(linear));
        const bool mirrors = glm::determinant(linear) < 0.0f;
        if (!mesh.HasTextureCoords(set))
            return fileError(path, name + " has no uv set " + std::to_string(set));
        const auto base = static_cast<unsigned>(data.vertices.size());
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            const std::string where = "vertex " + std::to_string(i) + " of " + name;
            if (!finite(mesh.mVertices[i]))
                return fileError(path,
                                 where + " has a non-finite position " + text(mesh.mVertices[i]));
            const aiVector3D uv = mesh.mTextureCoords[set][i];
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                return fileError(path, where + " has a non-finite uv");
            MeshVertex v{};
            v.position = glm::vec3(instance.model * glm::vec4(vec(mesh.mVertices[i]), 1.0f));
            // Assimp hands every format's uv with v up; the project's v runs down (glTF's).
            v.uv = {uv.x, 1.0f - uv.y};
            if (mesh.HasNormals()) {
                if (!finite(mesh.mNormals[i]))
                    return fileError(path, where + " has a non-finite normal");
                v.normal = normals * vec(mesh.mNormals[i]);
            }
            if (out.fileTangents) {
                // glTF: bitangent = w N x T points up the image; B = dP/dv points down it. w is
                // read after the transform, which a mirror flips.
                const glm::vec3 n = glm::normalize(v.normal), t = linear * vec(mesh.mTangents[i]);
                const float w =
                    glm::dot(linear * vec(mesh.mBitangents[i]), glm::cross(n, t)) >= 0.0f ? 1.0f
                                                                                          : -1.0f;
                const glm::vec3 tangent = t - n * glm::dot(n, t);
                if (!std::isfinite(glm::length(tangent)))
                    return fileError(path, where + " has a non-finite tangent");
                v.tangent = tangent;
                v.bitangent = -w * glm::cross(n, tangent);
            }
            data.vertices.push_back(v);
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3)
                continue;
            const unsigned a = base + face.mIndices[0], b = base + face.mIndices[mirrors ? 2 : 1],
                           c = base + face.mIndices[mirrors ? 1 : 2];
            if (degenerate(data.vertices[a], data.vertices[b], data.vertices[c])) {
                ++out.droppedTriangles;
                continue;
            }
            data.indices.insert(data.indices.end(), {a, b, c});
        }
    }
    if (data.indices.empty())
        return fileError(path, "every one of its " + std::to_string(triangles) +
                                   " triangles is degenerate (zero area in position or uv)");
    out.triangles = static_cast<int>(data.indices.size() / 3);
    if (out.droppedTriangles > 0)
        out.notes.push_back(path + ": dropped " + std::to_string(out.droppedTriangles) + " of " +
                            std::to_string(triangles) +
                            " triangles with zero area in position or uv");
    fillMissingNormals(data);
    out.fitScale = fitIntoUnitSphere(data);
    if (out.fileTangents)
        scaleFramesToUvDensity(data);
    else
        out.splitVertices = generateTangentFrames(data);
    return out;
}

} // namespace px
