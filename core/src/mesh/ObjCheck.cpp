// OBJ checked before Assimp, by one streaming pass in bounded memory: the faces' triangles and
// the vertices counted against the limit, the material libraries and their textures resolved
// under the mesh's root.

#include "MeshFileChecks.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <sstream>
#include <vector>

namespace px::mesh {

namespace {

constexpr std::size_t kChunk = 1 << 20;
constexpr std::size_t kMaxKeyword = 16;
constexpr std::size_t kMaxArgument = 4096; // a file name on a mtllib or map_ line

bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

std::string trimmed(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && blank(text[a]))
        ++a;
    while (b > a && blank(text[b - 1]))
        --b;
    return text.substr(a, b - a);
}

// Calls `line(keyword, argumentStart, tokens)` for each line of `file`: the first word, the first
// kMaxArgument characters after it, and how many words follow it. Memory stays at one chunk.
template <typename Line> Status eachLine(const InputFile& file, Line line) {
    std::vector<char> chunk(kChunk);
    std::string keyword, argument;
    std::uint64_t tokens = 0;
    bool inKeyword = true, inToken = false;
    for (std::uint64_t at = 0; at < file.size();) {
        const std::size_t n =
            static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, file.size() - at));
        if (Status s = file.readAt(at, chunk.data(), n); !s)
            return s;
        at += n;
        for (std::size_t i = 0; i < n; ++i) {
            const char c = chunk[i];
            if (c == '\n') {
                if (Status s = line(keyword, argument, tokens); !s)
                    return s;
                keyword.clear();
                argument.clear();
                tokens = 0;
                inKeyword = true;
                inToken = false;
                continue;
            }
            if (inKeyword) {
                if (blank(c)) {
                    inKeyword = keyword.empty();
                } else if (keyword.size() < kMaxKeyword) {
                    keyword += c;
                }
                continue;
            }
            if (argument.size() < kMaxArgument)
                argument += c;
            if (!blank(c) && !inToken)
                ++tokens;
            inToken = !blank(c);
        }
    }
    return line(keyword, argument, tokens);
}

bool textureStatement(const std::string& keyword) {
    static const char* names[] = {"bump", "disp", "decal", "refl", "norm"};
    return keyword.starts_with("map_") || std::any_of(std::begin(names), std::end(names),
                                                      [&](const char* n) { return keyword == n; });
}

// A material library: its textures are the mesh's files too (not read by the preview, but no
// output of the run may replace them).
Status checkLibrary(const std::filesystem::path& path, const MeshScope& scope) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return success(); // Assimp carries on without it, and so does the preview
    Result<InputFile> file = scope.open(path, "material library " + path.filename().string());
    if (!file)
        return file.error(); // a FIFO, or an output of the run
    return eachLine(
        *file,
        [&](const std::string& keyword, const std::string& argument, std::uint64_t) -> Status {
            if (!textureStatement(keyword))
                return success();
            const std::string rest = trimmed(argument);
            const std::size_t space = rest.find_last_of(" \t");
            const std::string name = space == std::string::npos ? rest : rest.substr(space + 1);
            if (name.empty())
                return success();
            Result<std::filesystem::path> texture = scope.resolve(
                name, "texture " + name + " of " + path.filename().string(), path.parent_path());
            if (!texture)
                return texture.error();
            return noteInput(texture->string(), "a texture of mesh " + scope.meshFile());
        });
}

// The material libraries a mtllib line names: one name with spaces, as Assimp reads it, or, when
// no such file is there, each word, as the format has it.
std::vector<std::string> libraryNames(const std::string& argument, const MeshScope& scope) {
    std::vector<std::string> names{trimmed(argument)};
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::path(scope.meshFile()).parent_path();
    if (!std::filesystem::exists(folder / names.front(), ec)) {
        std::istringstream words(names.front());
        names.assign(std::istream_iterator<std::string>(words), {});
    }
    return names;
}

} // namespace

Status checkObj(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles) {
    std::uint64_t triangles = 0, positions = 0, uvs = 0, normals = 0;
    std::vector<std::filesystem::path> libraries;
    const auto line = [&](const std::string& keyword, const std::string& argument,
                          std::uint64_t tokens) -> Status {
        if (keyword == "f" && tokens > 2)
            triangles += tokens - 2;
        else if (keyword == "v")
            ++positions;
        else if (keyword == "vt")
            ++uvs;
        else if (keyword == "vn")
            ++normals;
        else if (keyword == "mtllib" && !trimmed(argument).empty()) {
            for (const std::string& name : libraryNames(argument, scope)) {
                Result<std::filesystem::path> path =
                    scope.resolve(name, "material library " + name);
                if (!path)
                    return path.error();
                libraries.push_back(*path);
            }
        }
        return success();
    };
    if (Status s = eachLine(file, line); !s)
        return s;
    if (triangles > maxTriangles)
        return tooManyTriangles(scope.meshFile(), static_cast<std::size_t>(triangles),
                                maxTriangles);
    // No mesh within the limit uses more corners than three a triangle: more is memory Assimp
    // would spend on nothing.
    const std::uint64_t most = std::max<std::uint64_t>(3 * std::uint64_t{maxTriangles}, 3);
    if (std::max({positions, uvs, normals}) > most)
        return fileError(scope.meshFile(), std::to_string(std::max({positions, uvs, normals})) +
                                               " vertices, more than " +
                                               std::to_string(maxTriangles) +
                                               " triangles (the preview's limit) can use");
    for (const std::filesystem::path& library : libraries) {
        if (Status s = checkLibrary(library, scope); !s)
            return s;
    }
    return success();
}

} // namespace px::mesh
