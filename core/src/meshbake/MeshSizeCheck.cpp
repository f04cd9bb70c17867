#include "meshbake/MeshSizeCheck.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace px::meshbake {

namespace {

constexpr std::uint64_t kMaxHeader = 1 << 16;

int typeBytes(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
        return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
        return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64")
        return 8;
    return 0;
}

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t minBytes = 0; // binary: the least one instance can take
    std::uint64_t values = 0;   // ASCII: the least number of values one instance holds
};

} // namespace

Error tooManyTriangles(const std::string& file, std::size_t triangles, std::size_t limit) {
    return fileError(file, std::to_string(triangles) +
                               " triangles, more than the bake's limit of " +
                               std::to_string(limit));
}

Status checkPly(const InputFile& file, std::size_t maxTriangles) {
    const std::string& path = file.path();
    const auto headBytes = static_cast<std::size_t>(std::min(file.size(), kMaxHeader));
    std::string head(headBytes, '\0');
    if (Status s = file.readAt(0, head.data(), headBytes); !s)
        return s;
    const std::size_t end = head.find("end_header");
    if (!head.starts_with("ply") || end == std::string::npos)
        return fileError(path, "not a PLY file (no \"ply ... end_header\" header in its first " +
                                   std::to_string(kMaxHeader) + " bytes)");
    const std::size_t bodyStart = head.find('\n', end);
    if (bodyStart == std::string::npos)
        return fileError(path, "the PLY header does not end with a line break");
    std::istringstream lines(head.substr(0, end));
    std::string line, format;
    std::vector<PlyElement> elements;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format") {
            words >> format;
        } else if (keyword == "element") {
            PlyElement e;
            long long count = -1;
            words >> e.name >> count;
            if (!words || count < 0)
                return fileError(path, "a PLY element line without a count: \"" + line + "\"");
            e.count = static_cast<std::uint64_t>(count);
            elements.push_back(e);
        } else if (keyword == "property" && !elements.empty()) {
            std::string type;
            words >> type;
            PlyElement& e = elements.back();
            if (type == "list") {
                std::string countType, itemType, name;
                words >> countType >> itemType >> name;
                // A face has three corners at least; other lists may be empty.
                const bool corners = name == "vertex_indices" || name == "vertex_index";
                e.minBytes += static_cast<std::uint64_t>(typeBytes(countType)) +
                              (corners ? 3u * static_cast<std::uint64_t>(typeBytes(itemType)) : 0);
                e.values += corners ? 4 : 1;
            } else {
                e.minBytes += static_cast<std::uint64_t>(typeBytes(type));
                e.values += 1;
            }
        }
    }
    if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        return fileError(path, "unknown PLY format \"" + format + "\"");
    std::uint64_t faces = 0, least = 0;
    for (const PlyElement& e : elements) {
        if (e.name == "face")
            faces = e.count;
        // ASCII: every value takes a digit and a separator at least.
        const std::uint64_t each = format == "ascii" ? 2 * e.values : e.minBytes;
        if (each > 0 && e.count > (file.size() / each) + 1)
            return fileError(path, "the PLY header declares " + std::to_string(e.count) + " " +
                                       e.name + " elements, more than its " +
                                       std::to_string(file.size()) + " bytes can hold");
        least += e.count * each;
    }
    if (faces > maxTriangles)
        return tooManyTriangles(path, faces, maxTriangles);
    if (least > file.size() - (bodyStart + 1))
        return fileError(path, "the PLY file is truncated: its header declares at least " +
                                   std::to_string(least) + " bytes of data, it holds " +
                                   std::to_string(file.size() - (bodyStart + 1)));
    return success();
}

Status checkStl(const InputFile& file, std::size_t maxTriangles) {
    const std::string& path = file.path();
    if (file.size() < 15)
        return fileError(path,
                         "too short for an STL file (" + std::to_string(file.size()) + " bytes)");
    char start[5];
    if (Status s = file.readAt(0, start, 5); !s)
        return s;
    std::uint32_t count = 0;
    if (file.size() >= 84) {
        unsigned char bytes[4];
        if (Status s = file.readAt(80, bytes, 4); !s)
            return s;
        count = bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (std::uint32_t{bytes[3]} << 24);
    }
    const bool binary = file.size() >= 84 && file.size() == 84 + 50 * std::uint64_t{count};
    if (binary) {
        if (count > maxTriangles)
            return tooManyTriangles(path, count, maxTriangles);
        return success();
    }
    if (std::memcmp(start, "solid", 5) != 0)
        return fileError(path, "not an STL file: a binary STL of " + std::to_string(count) +
                                   " triangles takes " + std::to_string(84 + 50ull * count) +
                                   " bytes, the file holds " + std::to_string(file.size()));
    // ASCII: count the facets in bounded memory.
    constexpr std::size_t kChunk = 1 << 20;
    std::vector<char> chunk(kChunk + 8);
    std::uint64_t facets = 0;
    const std::string word = "endfacet";
    std::size_t carry = 0;
    for (std::uint64_t at = 0; at < file.size();) {
        const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, file.size() - at));
        if (Status s = file.readAt(at, chunk.data() + carry, n); !s)
            return s;
        at += n;
        const std::string_view text(chunk.data(), carry + n);
        for (std::size_t p = text.find(word); p != std::string_view::npos;
             p = text.find(word, p + word.size()))
            ++facets;
        // Keep the tail that could start a word cut by the chunk's end.
        carry = std::min<std::size_t>(word.size() - 1, text.size());
        std::memmove(chunk.data(), chunk.data() + text.size() - carry, carry);
    }
    if (facets > maxTriangles)
        return tooManyTriangles(path, facets, maxTriangles);
    return success();
}

} // namespace px::meshbake
