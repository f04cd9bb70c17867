#pragma once
// What a mesh file may reference: files under its root folder (the mesh's own folder unless the
// caller names another), each regular, opened without blocking and recorded as an input of the
// run (parallax/io/Inputs.h). Used by the checks before Assimp (GltfCheck, ObjCheck) and by the
// IOSystem through which Assimp opens every file, so that no reference can escape, hang or be
// written over.

#include "parallax/Result.h"
#include "parallax/io/Inputs.h"

#include <assimp/IOSystem.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace px::mesh {

class MeshScope {
public:
    // `meshFile` as the user named it; `root` empty: the mesh's folder.
    static Result<MeshScope> make(const std::string& meshFile, const std::string& root);

    // A reference as the file writes it (relative to `base`, by default the mesh's folder; glTF's
    // percent escapes already decoded) resolved and checked to lie under the root. `what`:
    // "buffer 0", ...
    Result<std::filesystem::path> resolve(const std::string& reference, const std::string& what,
                                          const std::filesystem::path& base = {}) const;
    // Opens a resolved reference (regular file, recorded as an input of the run).
    Result<InputFile> open(const std::filesystem::path& path, const std::string& what) const;

    const std::string& meshFile() const { return m_meshFile; }
    // Whether `path` (as Assimp spells it) lies under the root.
    bool inside(const std::filesystem::path& path) const;

private:
    MeshScope() = default;
    std::string m_meshFile;
    std::filesystem::path m_folder; // the mesh's folder, as given
    std::filesystem::path m_root;   // canonical
};

// glTF URIs escape bytes as %XX: "my%20mesh.bin" names "my mesh.bin".
std::string percentDecoded(const std::string& uri);

// The IOSystem Assimp opens every file through: only files under the scope's root, regular,
// recorded. A refusal (outside the root, a special file, an output of the run) is kept and fails
// the load even where Assimp would carry on without the file; a missing file is Assimp's to judge.
class ScopedIoSystem : public Assimp::IOSystem {
public:
    explicit ScopedIoSystem(const MeshScope& scope) : m_scope(scope) {}
    bool Exists(const char* file) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override;
    void Close(Assimp::IOStream* stream) override;
    const std::string& refusal() const { return m_refusal; }
    // Every file Assimp opened, in order (the mesh, its material libraries, buffers).
    const std::vector<std::filesystem::path>& opened() const { return m_opened; }

private:
    const MeshScope& m_scope;
    std::string m_refusal;
    std::vector<std::filesystem::path> m_opened;
};

} // namespace px::mesh
