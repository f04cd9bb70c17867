#include "GlslUnit.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <map>
#include <optional>

namespace px::shader {

namespace {

bool isIdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

Error lineError(const std::string& path, int line, const std::string& problem) {
    return Error{path + ":" + std::to_string(line) + ": " + problem};
}

// A #if expression over defined names: defined(X), X, !, &&, ||, parentheses, 0 and 1.
class Condition {
public:
    Condition(std::string_view text, const std::set<std::string>& defines)
        : m_text(text), m_defines(defines) {}

    std::optional<bool> evaluate() {
        const std::optional<bool> value = orExpr();
        skipSpace();
        if (!value || m_pos != m_text.size())
            return std::nullopt;
        return value;
    }

private:
    void skipSpace() {
        while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos])))
            ++m_pos;
    }
    bool accept(std::string_view token) {
        skipSpace();
        if (m_text.substr(m_pos, token.size()) != token)
            return false;
        m_pos += token.size();
        return true;
    }
    std::string identifier() {
        skipSpace();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && isIdentChar(m_text[m_pos]))
            ++m_pos;
        return std::string(m_text.substr(start, m_pos - start));
    }
    std::optional<bool> orExpr() {
        std::optional<bool> value = andExpr();
        while (value && accept("||")) {
            const std::optional<bool> rhs = andExpr();
            if (!rhs)
                return std::nullopt;
            value = *value || *rhs;
        }
        return value;
    }
    std::optional<bool> andExpr() {
        std::optional<bool> value = unary();
        while (value && accept("&&")) {
            const std::optional<bool> rhs = unary();
            if (!rhs)
                return std::nullopt;
            value = *value && *rhs;
        }
        return value;
    }
    std::optional<bool> unary() {
        if (accept("!")) {
            const std::optional<bool> value = unary();
            return value ? std::optional<bool>(!*value) : std::nullopt;
        }
        if (accept("(")) {
            const std::optional<bool> value = orExpr();
            return value && accept(")") ? value : std::nullopt;
        }
        const std::string name = identifier();
        if (name.empty())
            return std::nullopt;
        if (name == "defined") {
            const bool paren = accept("(");
            const std::string macro = identifier();
            if (macro.empty() || (paren && !accept(")")))
                return std::nullopt;
            return m_defines.count(macro) > 0;
        }
        if (name == "0" || name == "1")
            return name == "1";
        return m_defines.count(name) > 0;
    }

    std::string_view m_text;
    const std::set<std::string>& m_defines;
    std::size_t m_pos = 0;
};

// The code of an item without its comments (kept newline-free where comments were).
std::string stripComments(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n')
                ++i;
            out += '\n';
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t end = text.find("*/", i + 2);
            i = end == std::string_view::npos ? text.size() : end + 1;
            out += ' ';
        } else {
            out += text[i];
        }
    }
    return out;
}

// Identifiers in code, numeric literals (1.0e30f) skipped whole.
std::vector<std::string> identifiers(std::string_view code) {
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < code.size();) {
        if (std::isdigit(static_cast<unsigned char>(code[i]))) {
            while (i < code.size() && (isIdentChar(code[i]) || code[i] == '.'))
                ++i;
        } else if (isIdentStart(code[i])) {
            const std::size_t start = i;
            while (i < code.size() && isIdentChar(code[i]))
                ++i;
            ids.emplace_back(code.substr(start, i - start));
        } else {
            ++i;
        }
    }
    return ids;
}

// The names a code item declares: a struct's tag, a function's name, or each declarator of a
// global ("int a, b;" declares a and b). A declarator's name is its last identifier before its
// '=', '[' or the comma or ';' that ends it; commas inside (), [] and {} do not split.
// The members a block body declares ("float a[]; uint b;" up to its '}'): the last identifier
// before each top-level '[' or ';'.
std::vector<std::string> blockMembers(std::string_view body) {
    std::vector<std::string> names;
    std::string last;
    bool named = false;
    for (std::size_t i = 0; i < body.size() && body[i] != '}'; ++i) {
        const char c = body[i];
        if (isIdentStart(c)) {
            const std::size_t start = i;
            while (i + 1 < body.size() && isIdentChar(body[i + 1]))
                ++i;
            last = std::string(body.substr(start, i + 1 - start));
        } else if ((c == '[' || c == ';') && !named && !last.empty()) {
            names.push_back(last);
            named = c == '[';
        } else if (c == ';') {
            named = false;
        }
    }
    return names;
}

std::vector<std::string> declaredNames(std::string_view code) {
    std::vector<std::string> names;
    std::vector<std::string> words; // the current declarator's identifiers at depth 0
    bool named = false;             // its '=' or '[' was seen: no later identifier is its name
    std::string beforeParen;        // the identifier before the first top-level '('
    int depth = 0;
    auto endDeclarator = [&] {
        if (!words.empty())
            names.push_back(words.back());
        words.clear();
        named = false;
    };
    for (std::size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        if (c == '(' || c == '[' || c == '{') {
            if (depth == 0 && c == '(' && beforeParen.empty() && !words.empty() && names.empty())
                beforeParen = words.back();
            if (depth == 0 && c == '{') {
                if (words.size() >= 2 && words.front() == "struct")
                    return {words[1]};
                // A storage block (layout(...) readonly buffer Name { T member[]; ... };): its
                // members are what code names.
                if (std::find(words.begin(), words.end(), "buffer") != words.end())
                    return blockMembers(code.substr(i + 1));
                if (!beforeParen.empty())
                    return {beforeParen}; // a function's body
            }
            if (depth == 0 && c == '[')
                named = true;
            ++depth;
        } else if (c == ')' || c == ']' || c == '}') {
            --depth;
        } else if (depth == 0 && c == '=') {
            named = true;
        } else if (depth == 0 && c == ',') {
            endDeclarator();
        } else if (depth == 0 && c == ';') {
            break;
        } else if (isIdentStart(c)) {
            const std::size_t start = i;
            while (i + 1 < code.size() && isIdentChar(code[i + 1]))
                ++i;
            if (depth == 0 && !named)
                words.emplace_back(code.substr(start, i + 1 - start));
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i + 1 < code.size() && (isIdentChar(code[i + 1]) || code[i + 1] == '.'))
                ++i;
        }
    }
    endDeclarator();
    return names;
}

} // namespace

Result<std::string> preprocess(std::string_view text, const std::set<std::string>& defines,
                               const std::string& path) {
    struct Frame {
        bool parentActive;
        bool active;
        bool taken; // some branch of this #if was taken already
    };
    std::vector<Frame> stack;
    bool active = true;
    std::string out;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t end = text.find('\n', pos);
        const bool last = end == std::string_view::npos;
        if (last)
            end = text.size();
        const std::string_view line = text.substr(pos, end - pos);
        ++lineNo;
        std::size_t k = line.find_first_not_of(" \t");
        const bool directive = k != std::string_view::npos && line[k] == '#';
        std::string word;
        std::string_view rest;
        if (directive) {
            k = line.find_first_not_of(" \t", k + 1);
            std::size_t w = k;
            while (w != std::string_view::npos && w < line.size() && isIdentChar(line[w]))
                ++w;
            if (k != std::string_view::npos) {
                word = std::string(line.substr(k, w - k));
                rest = line.substr(w);
            }
        }
        if (!line.empty() && line.back() == '\\')
            return lineError(path, lineNo, "line continuations are not supported in shader files");
        auto condition = [&](std::string_view expr) -> std::optional<bool> {
            if (word == "ifdef" || word == "ifndef") {
                const std::string name = std::string(expr.substr(expr.find_first_not_of(" \t")));
                const std::size_t e = name.find_first_of(" \t/");
                const bool defined = defines.count(name.substr(0, e)) > 0;
                return word == "ifdef" ? defined : !defined;
            }
            return Condition(expr, defines).evaluate();
        };
        bool keepLine = active;
        if (word == "if" || word == "ifdef" || word == "ifndef") {
            const std::optional<bool> c = condition(rest);
            if (!c)
                return lineError(path, lineNo, "cannot evaluate #" + word + std::string(rest));
            stack.push_back({active, *c, *c});
            active = active && *c;
            keepLine = false;
        } else if (word == "elif" || word == "else") {
            if (stack.empty())
                return lineError(path, lineNo, "#" + word + " without #if");
            Frame& f = stack.back();
            if (word == "elif") {
                const std::optional<bool> c =
                    f.taken ? std::optional<bool>(false) : condition(rest);
                if (!c)
                    return lineError(path, lineNo, "cannot evaluate #elif" + std::string(rest));
                f.active = *c;
            } else {
                f.active = !f.taken;
            }
            f.taken = f.taken || f.active;
            active = f.parentActive && f.active;
            keepLine = false;
        } else if (word == "endif") {
            if (stack.empty())
                return lineError(path, lineNo, "#endif without #if");
            active = stack.back().parentActive;
            stack.pop_back();
            keepLine = false;
        }
        if (keepLine)
            out += line;
        if (!last)
            out += '\n';
        if (last)
            break;
        pos = end + 1;
    }
    if (!stack.empty())
        return lineError(path, lineNo, "#if without #endif");
    return out;
}

Result<std::vector<GlslItem>> splitItems(std::string_view text, int file, const std::string& path) {
    std::vector<GlslItem> items;
    const std::size_t n = text.size();
    std::size_t i = 0;
    int line = 1;
    std::size_t lineStart = 0;
    bool lineHasContent = false;
    std::size_t pendingStart = std::string_view::npos; // comment lines directly above an item
    int pendingLine = 0;

    auto finishItem = [&](std::size_t start, int firstLine, std::size_t end) {
        // Take the rest of the line (a trailing comment, the newline) with the item.
        while (end < n && text[end] != '\n')
            ++end;
        if (end < n)
            ++end;
        GlslItem item;
        item.file = file;
        item.firstLine = firstLine;
        item.text = std::string(text.substr(start, end - start));
        if (item.text.empty() || item.text.back() != '\n')
            item.text += '\n';
        const std::string code = stripComments(item.text);
        const std::size_t hash = code.find_first_not_of(" \t\n");
        if (hash != std::string::npos && code[hash] == '#') {
            const std::vector<std::string> ids = identifiers(code);
            if (ids.size() >= 2 && ids[0] == "define")
                item.names.push_back(ids[1]);
            for (std::size_t k = 2; k < ids.size(); ++k)
                item.references.insert(ids[k]);
        } else {
            item.names = declaredNames(code);
            for (std::string& id : identifiers(code)) {
                if (std::find(item.names.begin(), item.names.end(), id) == item.names.end())
                    item.references.insert(std::move(id));
            }
        }
        items.push_back(std::move(item));
        for (std::size_t k = start; k < end; ++k) {
            if (text[k] == '\n')
                ++line;
        }
        i = end;
        lineStart = end;
        lineHasContent = false;
        pendingStart = std::string_view::npos;
    };

    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            if (!lineHasContent)
                pendingStart = std::string_view::npos; // a blank line detaches comments above it
            ++line;
            ++i;
            lineStart = i;
            lineHasContent = false;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
            continue;
        }
        if (text.compare(i, 2, "//") == 0 || text.compare(i, 2, "/*") == 0) {
            if (pendingStart == std::string_view::npos) {
                pendingStart = lineStart;
                pendingLine = line;
            }
            lineHasContent = true;
            if (text[i + 1] == '/') {
                while (i < n && text[i] != '\n')
                    ++i;
            } else {
                const std::size_t end = text.find("*/", i + 2);
                if (end == std::string_view::npos)
                    return lineError(path, line, "unterminated comment");
                for (std::size_t k = i; k < end; ++k) {
                    if (text[k] == '\n') {
                        ++line;
                        lineStart = k + 1;
                    }
                }
                i = end + 2;
            }
            continue;
        }
        const std::size_t start = pendingStart != std::string_view::npos ? pendingStart : lineStart;
        const int firstLine = pendingStart != std::string_view::npos ? pendingLine : line;
        // Count lines from `start` again in finishItem: rewind the counter to the item's start.
        line = firstLine;
        if (c == '#') {
            finishItem(start, firstLine, i);
            continue;
        }
        int parens = 0;
        int braces = 0;
        // Structs and storage blocks end at their ';', not at their '}'.
        const std::string_view head = text.substr(i, text.find_first_of("{;", i) - i);
        bool isStruct =
            (text.compare(i, 6, "struct") == 0 && (i + 6 < n && !isIdentChar(text[i + 6]))) ||
            head.find(" buffer ") != std::string_view::npos;
        std::size_t end = std::string_view::npos;
        int scanLine = line;
        for (std::size_t k = i; k < n; ++k) {
            const char ch = text[k];
            if (text.compare(k, 2, "//") == 0) {
                while (k + 1 < n && text[k + 1] != '\n')
                    ++k;
            } else if (text.compare(k, 2, "/*") == 0) {
                const std::size_t e = text.find("*/", k + 2);
                if (e == std::string_view::npos)
                    return lineError(path, scanLine, "unterminated comment");
                k = e + 1;
            } else if (ch == '\n') {
                ++scanLine;
            } else if (ch == '(') {
                ++parens;
            } else if (ch == ')') {
                --parens;
            } else if (ch == '{') {
                ++braces;
            } else if (ch == '}') {
                if (--braces < 0)
                    return lineError(path, scanLine, "unbalanced '}'");
                if (braces == 0 && !isStruct) {
                    end = k + 1;
                    break;
                }
            } else if (ch == ';' && braces == 0 && parens == 0) {
                end = k + 1;
                break;
            }
        }
        if (end == std::string_view::npos)
            return lineError(path, line, "declaration without its end (a missing '}' or ';')");
        finishItem(start, firstLine, end);
    }
    return items;
}

std::vector<const GlslItem*> reachableItems(const std::vector<GlslItem>& items,
                                            const std::vector<std::string>& roots,
                                            std::set<std::string>& external) {
    std::vector<const GlslItem*> pointers;
    pointers.reserve(items.size());
    for (const GlslItem& item : items)
        pointers.push_back(&item);
    return reachableItems(pointers, roots, external);
}

std::vector<const GlslItem*> reachableItems(const std::vector<const GlslItem*>& items,
                                            const std::vector<std::string>& roots,
                                            std::set<std::string>& external) {
    std::multimap<std::string, std::size_t> byName;
    for (std::size_t k = 0; k < items.size(); ++k) {
        for (const std::string& name : items[k]->names)
            byName.emplace(name, k);
    }
    std::vector<bool> kept(items.size(), false);
    std::deque<std::string> queue(roots.begin(), roots.end());
    std::set<std::string> seen(roots.begin(), roots.end());
    while (!queue.empty()) {
        const std::string name = queue.front();
        queue.pop_front();
        auto [first, last] = byName.equal_range(name);
        if (first == last) {
            external.insert(name);
            continue;
        }
        for (auto it = first; it != last; ++it) {
            kept[it->second] = true;
            for (const std::string& ref : items[it->second]->references) {
                if (seen.insert(ref).second)
                    queue.push_back(ref);
            }
        }
    }
    std::vector<const GlslItem*> result;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (kept[k])
            result.push_back(items[k]);
    }
    return result;
}

} // namespace px::shader
