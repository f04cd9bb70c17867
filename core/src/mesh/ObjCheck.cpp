// OBJ checked before Assimp, by one streaming pass in bounded memory that cuts and reads lines as
// Assimp's ObjFileParser does: the corners of its face, line and point statements and its
// vertices counted against the limit, the material libraries and their textures resolved under
// the mesh's root.

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
// A run of characters between separators in a face statement: "-123456789" is the longest index
// the preview could ever use; anything longer is refused rather than read as atoi reads it.
constexpr std::size_t kMaxIndexText = 10;

bool blank(char c) {
    return c == ' ' || c == '\t';
}

// Assimp's IsLineEnd.
bool lineEnd(char c) {
    return c == '\r' || c == '\n' || c == '\0' || c == '\f';
}

std::string trimmed(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && (blank(text[a]) || text[a] == '\r'))
        ++a;
    while (b > a && (blank(text[b - 1]) || text[b - 1] == '\r'))
        --b;
    return text.substr(a, b - a);
}

// Feeds `sink` each line of `file` as Assimp's OBJ reader cuts them
// (IOStreamBuffer::getNextDataLine): a line ends at CR, LF, NUL or FF; a `\` just before a line
// end joins the next line, dropping everything up to the next LF and keeping the character after
// it whatever it is. `sink.put(c)` sees every character of a line, `sink.end()` its end. Memory
// stays at one chunk.
template <typename Sink> Status eachLine(const InputFile& file, Sink& sink) {
    std::vector<char> chunk(kChunk);
    enum class State { Plain, Backslash, Skip, Keep } state = State::Plain;
    for (std::uint64_t at = 0; at < file.size();) {
        const std::size_t n =
            static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, file.size() - at));
        if (Status s = file.readAt(at, chunk.data(), n); !s)
            return s;
        at += n;
        for (std::size_t i = 0; i < n; ++i) {
            const char c = chunk[i];
            if (state == State::Skip) {
                if (c == '\n')
                    state = State::Keep;
                continue;
            }
            if (state == State::Keep) {
                sink.put(c);
                state = State::Plain;
                continue;
            }
            if (state == State::Backslash) {
                if (lineEnd(c)) {
                    state = c == '\n' ? State::Keep : State::Skip;
                    continue;
                }
                sink.put('\\');
                state = State::Plain;
            }
            if (c == '\\') {
                state = State::Backslash;
            } else if (lineEnd(c)) {
                if (Status s = sink.end(); !s)
                    return s;
            } else {
                sink.put(c);
            }
        }
    }
    if (state == State::Backslash)
        sink.put('\\');
    return sink.end();
}

// The corners Assimp's ObjFileParser::getFace reads from the body of a face, line or point
// statement: after the keyword, runs of characters between separators (blanks, `/`); a number in
// the first slot of a corner (before any `/`) is a vertex index. atoi reads each, and Assimp moves
// on by the digits of its value, so "0001" is four corners: that is counted too.
class CornerCounter {
public:
    void reset() {
        m_run.clear();
        m_slot = 0;
        m_corners = 0;
        m_done = false;
        m_tooLong = false;
    }
    void put(char c) {
        if (m_done)
            return;
        if (c == '#' || lineEnd(c)) {
            endRun();
            m_done = true;
        } else if (c == '/') {
            endRun();
            ++m_slot;
        } else if (blank(c) || c == '\v') {
            endRun();
            m_slot = 0;
        } else if (m_run.size() < kMaxIndexText) {
            m_run += c;
        } else {
            m_tooLong = true;
        }
    }
    std::uint64_t finish() {
        endRun();
        return m_corners;
    }
    bool tooLong() const { return m_tooLong; }

private:
    void endRun() {
        if (m_tooLong || m_run.empty()) {
            m_run.clear();
            return;
        }
        for (std::size_t i = 0; i < m_run.size();) {
            // atoi at i: a sign, then digits (at most 10 characters: it fits an int).
            std::size_t j = i;
            const bool negative = m_run[j] == '-';
            if (m_run[j] == '-' || m_run[j] == '+')
                ++j;
            long long value = 0;
            for (; j < m_run.size() && std::isdigit(static_cast<unsigned char>(m_run[j])); ++j)
                value = value * 10 + (m_run[j] - '0');
            value = negative ? -value : value;
            std::size_t step = value < 0 ? 2 : 1;
            for (long long rest = value; (rest /= 10) != 0;)
                ++step;
            if (m_slot == 0 && value != 0)
                ++m_corners;
            i += step;
        }
        m_run.clear();
    }

    std::string m_run;
    std::uint64_t m_slot = 0, m_corners = 0;
    bool m_done = false, m_tooLong = false;
};

// What one pass over an OBJ counts, reading each line as ObjFileParser::parseFile does: by its
// first character ('v' then a blank: a position, "vt", "vn"; 'f', 'l', 'p': a face, line or point
// statement, whatever follows), skipping the lines of a cstype ... end block.
class ObjCounter {
public:
    std::uint64_t triangles = 0, otherFaces = 0, corners = 0, positions = 0, uvs = 0, normals = 0;
    std::vector<std::string> libraries; // mtllib arguments
    bool tooLongIndex = false;

    void put(char c) {
        if (m_length < 3 && m_firstLine && static_cast<unsigned char>(c) == kBom[m_length] &&
            m_bom == m_length) {
            ++m_bom; // a UTF-8 byte order mark, skipped on the first line
            ++m_length;
            return;
        }
        const std::size_t at = m_length++ - m_bom;
        if (at < 2)
            m_head[at] = c;
        if (m_inKeyword && !blank(c)) {
            if (m_keyword.size() < kMaxKeyword)
                m_keyword += c;
        } else if (m_inKeyword) {
            m_inKeyword = false;
        }
        if (!m_inKeyword && m_argument.size() < kMaxArgument && !(m_argument.empty() && blank(c)))
            m_argument += c;
        if (!m_inKeyword && face())
            m_counter.put(c);
    }

    Status end() {
        if (m_cstype) {
            m_cstype = m_keyword != "end";
        } else if (face()) {
            const std::uint64_t n = m_counter.finish();
            tooLongIndex = tooLongIndex || m_counter.tooLong();
            corners += n;
            if (m_head[0] == 'f')
                triangles += n > 2 ? n - 2 : 0;
            else if (m_head[0] == 'l')
                otherFaces += n > 1 ? n - 1 : 0;
            else
                otherFaces += n;
        } else if (m_head[0] == 'v' && m_length > m_bom + 1) {
            if (blank(m_head[1]))
                ++positions;
            else if (m_head[1] == 't')
                ++uvs;
            else if (m_head[1] == 'n')
                ++normals;
        } else if (m_keyword == "mtllib" && !m_argument.empty()) {
            libraries.push_back(m_argument);
        } else if (m_head[0] == 'c') {
            m_cstype = m_keyword == "cstype";
        }
        m_firstLine = false; // Assimp skips a byte order mark on the first line only
        m_length = m_bom = 0;
        m_head[0] = m_head[1] = '\0';
        m_keyword.clear();
        m_argument.clear();
        m_inKeyword = true;
        m_counter.reset();
        return success();
    }

private:
    bool face() const {
        return !m_cstype && (m_head[0] == 'f' || m_head[0] == 'l' || m_head[0] == 'p');
    }

    static constexpr unsigned char kBom[3] = {0xEF, 0xBB, 0xBF};
    std::size_t m_length = 0, m_bom = 0;
    char m_head[2] = {'\0', '\0'};
    std::string m_keyword, m_argument;
    bool m_inKeyword = true, m_firstLine = true, m_cstype = false;
    CornerCounter m_counter;
};

// The lines of a material library as Assimp's ObjFileMtlImporter cuts them (at CR, LF, NUL or
// FF): each line's keyword and the text after it.
class MtlLines {
public:
    template <typename Line> Status read(const InputFile& file, Line line) {
        std::vector<char> chunk(kChunk);
        for (std::uint64_t at = 0; at < file.size();) {
            const std::size_t n =
                static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, file.size() - at));
            if (Status s = file.readAt(at, chunk.data(), n); !s)
                return s;
            at += n;
            for (std::size_t i = 0; i < n; ++i) {
                const char c = chunk[i];
                if (lineEnd(c)) {
                    if (Status s = flush(line); !s)
                        return s;
                } else if (m_inKeyword && blank(c)) {
                    m_inKeyword = m_keyword.empty();
                } else if (m_inKeyword) {
                    if (m_keyword.size() < kMaxKeyword)
                        m_keyword += c;
                } else if (m_argument.size() < kMaxArgument) {
                    m_argument += c;
                }
            }
        }
        return flush(line);
    }

private:
    template <typename Line> Status flush(Line& line) {
        Status s = line(m_keyword, m_argument);
        m_keyword.clear();
        m_argument.clear();
        m_inKeyword = true;
        return s;
    }
    std::string m_keyword, m_argument;
    bool m_inKeyword = true;
};

bool textureStatement(const std::string& keyword) {
    static const char* names[] = {"bump", "disp", "decal", "refl", "norm"};
    std::string lower = keyword;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower.starts_with("map") || std::any_of(std::begin(names), std::end(names),
                                                   [&](const char* n) { return lower == n; });
}

// The names a texture statement's argument may stand for: Assimp takes the text after its
// options (-bm 0.5, -o 1 1 1, ...) to the end of the line, spaces and all ("my tex.png"); other
// readers take the last word. Each tail of the argument that starts after a blank is one.
std::vector<std::string> textureNames(const std::string& argument) {
    std::vector<std::string> names;
    const std::string text = trimmed(argument);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i == 0 || (blank(text[i - 1]) && !blank(text[i])))
            names.push_back(text.substr(i));
    }
    return names;
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
    MtlLines lines;
    return lines.read(
        *file, [&](const std::string& keyword, const std::string& argument) -> Status {
            if (!textureStatement(keyword))
                return success();
            for (const std::string& name : textureNames(argument)) {
                Result<std::filesystem::path> texture =
                    scope.resolve(name, "texture " + name + " of " + path.filename().string(),
                                  path.parent_path());
                if (!texture)
                    return texture.error();
                if (Status s =
                        noteInput(texture->string(), "a texture of mesh " + scope.meshFile());
                    !s)
                    return s;
            }
            return success();
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
    ObjCounter counts;
    if (Status s = eachLine(file, counts); !s)
        return s;
    if (counts.tooLongIndex)
        return fileError(scope.meshFile(),
                         "cannot read it as a mesh: a face, line or point statement holds an "
                         "index of more than " +
                             std::to_string(kMaxIndexText) + " characters");
    if (counts.otherFaces == 0 && counts.triangles > maxTriangles)
        return tooManyTriangles(scope.meshFile(), static_cast<std::size_t>(counts.triangles),
                                maxTriangles);
    if (counts.triangles + counts.otherFaces > maxTriangles)
        return fileError(scope.meshFile(),
                         std::to_string(counts.triangles + counts.otherFaces) +
                             " points, lines and triangles, more than the preview's limit of " +
                             std::to_string(maxTriangles));
    // No mesh within the limit uses more corners or vertices than three a triangle: more is
    // memory Assimp would spend on nothing.
    const std::uint64_t most = std::max<std::uint64_t>(3 * std::uint64_t{maxTriangles}, 3);
    if (counts.corners > most)
        return fileError(scope.meshFile(), std::to_string(counts.corners) +
                                               " corners in its faces, more than " +
                                               std::to_string(maxTriangles) +
                                               " triangles (the preview's limit) can use");
    const std::uint64_t vertices = std::max({counts.positions, counts.uvs, counts.normals});
    if (vertices > most)
        return fileError(scope.meshFile(), std::to_string(vertices) + " vertices, more than " +
                                               std::to_string(maxTriangles) +
                                               " triangles (the preview's limit) can use");
    std::vector<std::filesystem::path> libraries;
    for (const std::string& argument : counts.libraries) {
        for (const std::string& name : libraryNames(argument, scope)) {
            Result<std::filesystem::path> path = scope.resolve(name, "material library " + name);
            if (!path)
                return path.error();
            libraries.push_back(*path);
        }
    }
    // Assimp reads MESH.mtl when a library named cannot be opened.
    if (!libraries.empty()) {
        std::filesystem::path fallback = scope.meshFile();
        fallback.replace_extension(".mtl");
        libraries.push_back(fallback);
    }
    for (const std::filesystem::path& library : libraries) {
        if (Status s = checkLibrary(library, scope); !s)
            return s;
    }
    return success();
}

} // namespace px::mesh
