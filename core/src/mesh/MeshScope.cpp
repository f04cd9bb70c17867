#include "MeshScope.h"

#include <algorithm>
#include <assimp/IOStream.hpp>
#include <cerrno>
#include <unistd.h>

namespace px::mesh {

namespace fs = std::filesystem;

namespace {

fs::path canonicalOf(const fs::path& path) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path, ec).lexically_normal() : canonical;
}

bool under(const fs::path& path, const fs::path& root) {
    auto [r, p] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
    return r == root.end();
}

// Assimp's reads, from an InputFile.
class InputStream : public Assimp::IOStream {
public:
    explicit InputStream(InputFile file) : m_file(std::move(file)) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0 || m_at >= m_file.size())
            return 0;
        const std::uint64_t left = m_file.size() - m_at;
        const size_t items = static_cast<size_t>(std::min<std::uint64_t>(count, left / size));
        if (items == 0 || !m_file.readAt(m_at, buffer, items * size))
            return 0;
        m_at += items * size;
        return items;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        const std::uint64_t base = origin == aiOrigin_SET   ? 0
                                   : origin == aiOrigin_CUR ? m_at
                                                            : m_file.size();
        if (base + offset > m_file.size())
            return aiReturn_FAILURE;
        m_at = base + offset;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return static_cast<size_t>(m_at); }
    size_t FileSize() const override { return static_cast<size_t>(m_file.size()); }
    void Flush() override {}

private:
    InputFile m_file;
    std::uint64_t m_at = 0;
};

} // namespace

Result<MeshScope> MeshScope::make(const std::string& meshFile, const std::string& root) {
    MeshScope scope;
    scope.m_meshFile = meshFile;
    scope.m_folder = fs::path(meshFile).parent_path();
    const fs::path given = root.empty() ? scope.m_folder : fs::path(root);
    std::error_code ec;
    if (!root.empty() && !fs::is_directory(given, ec))
        return fileError(root, "the mesh root is not a folder");
    scope.m_root = canonicalOf(given.empty() ? fs::path(".") : given);
    return scope;
}

bool MeshScope::inside(const fs::path& path) const {
    return under(canonicalOf(path), m_root);
}

Result<fs::path> MeshScope::resolve(const std::string& reference, const std::string& what,
                                    const fs::path& base) const {
    const std::size_t colon = reference.find(':');
    if (colon != std::string::npos && colon > 1 && reference.find('/') > colon)
        return fileError(m_meshFile, what + " refers to " + reference +
                                         ", which is not a file beside the mesh (only relative "
                                         "file names are read)");
    const fs::path path = fs::path(reference).is_absolute() ? fs::path(reference)
                          : base.empty()                    ? m_folder / reference
                                                            : base / reference;
    if (!inside(path))
        return fileError(m_meshFile, what + " refers to " + reference + ", outside the folder " +
                                         m_root.string() +
                                         " (a mesh reads only files under its own folder; "
                                         "--mesh-root DIR allows a wider one)");
    return path.lexically_normal();
}

Result<InputFile> MeshScope::open(const fs::path& path, const std::string& what) const {
    Result<InputFile> file = InputFile::open(path.string(), what + " of mesh " + m_meshFile);
    if (!file)
        return fileError(m_meshFile, what + ": " + file.error().message);
    return file;
}

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        const auto hex = [](char c) {
            return c >= '0' && c <= '9'   ? c - '0'
                   : c >= 'a' && c <= 'f' ? c - 'a' + 10
                   : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                          : -1;
        };
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool ScopedIoSystem::Exists(const char* file) const {
    std::error_code ec;
    return file != nullptr && m_scope.inside(file) && fs::exists(file, ec);
}

Assimp::IOStream* ScopedIoSystem::Open(const char* file, const char* mode) {
    if (file == nullptr || mode == nullptr ||
        std::string(mode).find_first_of("wa+") != std::string::npos)
        return nullptr;
    if (!m_scope.inside(file)) {
        m_refusal = std::string(file) + " lies outside the mesh's folder";
        return nullptr;
    }
    std::error_code ec;
    if (!fs::exists(file, ec))
        return nullptr; // Assimp probes for optional files
    Result<InputFile> opened = m_scope.open(file, "a file it refers to");
    if (!opened) {
        m_refusal = opened.error().message;
        return nullptr;
    }
    m_opened.emplace_back(file);
    return new InputStream(std::move(*opened));
}

void ScopedIoSystem::Close(Assimp::IOStream* stream) {
    delete stream;
}

} // namespace px::mesh
