#include "parallax/material/MapFileName.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace px {

namespace {

bool isLower(char c) {
    return std::islower(static_cast<unsigned char>(c)) != 0;
}
bool isUpper(char c) {
    return std::isupper(static_cast<unsigned char>(c)) != 0;
}
bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isAlnum(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

bool allDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), isDigit);
}

// A digit run and the word glued after it that together say one thing: "2" "k", "16" "bit",
// "lod" "0", "var" "1", "1024" "x" "1024".
bool joinsWith(const NameWord& a, const NameWord& b) {
    if (!b.glued)
        return false;
    if (allDigits(a.text))
        return b.text == "k" || b.text == "bit" || b.text == "x";
    if (a.text.size() > 1 && a.text.back() == 'x' && allDigits(a.text.substr(0, a.text.size() - 1)))
        return allDigits(b.text); // 1024x1024
    return (a.text == "lod" || a.text == "var") && allDigits(b.text);
}

// Bit depth glued to a tag: "DISP16", "NRM16", "BUMP16" (Poliigon).
bool isGluedBitDepth(const NameWord& w) {
    return w.glued && (w.text == "8" || w.text == "16" || w.text == "32");
}

// The stem before word `k`: up to the end of the last word that is not neutral.
std::string stemBefore(std::string_view name, const std::vector<NameWord>& words, std::size_t k) {
    while (k > 0 && isNeutralWord(words[k - 1].text))
        --k;
    return k == 0 ? std::string() : std::string(name.substr(0, words[k - 1].end));
}

// The tag of `words[..end)`'s last words, longest first: {first word index, tag}.
std::pair<std::size_t, const MapTag*> tagEndingAt(const std::vector<NameWord>& words,
                                                  std::size_t end) {
    for (std::size_t n = std::min<std::size_t>(3, end); n >= 1; --n) {
        std::string text;
        for (std::size_t i = end - n; i < end; ++i)
            text += (text.empty() ? "" : " ") + words[i].text;
        if (const MapTag* tag = findMapTag(text))
            return {end - n, tag};
    }
    return {end, nullptr};
}

bool isNormalRole(MapRole role) {
    return role == MapRole::Normal || role == MapRole::NormalGloss;
}

} // namespace

std::vector<NameWord> splitName(std::string_view stem) {
    std::vector<NameWord> words;
    bool glued = false; // how the next word meets the one before
    for (std::size_t i = 0; i < stem.size();) {
        if (!isAlnum(stem[i])) {
            glued = false;
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        bool nextGlued = false;
        for (; j < stem.size() && isAlnum(stem[j]); ++j) {
            const char a = stem[j - 1], b = stem[j];
            const bool camel =
                (isLower(a) && isUpper(b)) || (isUpper(a) && isUpper(b) && j + 1 < stem.size() &&
                                               isLower(stem[j + 1])); // "HDRPMask": HDRP | Mask
            if (camel || isDigit(a) != isDigit(b)) {
                nextGlued = !camel; // letters against digits: glued; a case change is not
                break;
            }
        }
        NameWord w{lower(stem.substr(i, j - i)), i, j, glued};
        if (!words.empty() && joinsWith(words.back(), w)) {
            words.back().text += w.text;
            words.back().end = w.end;
        } else {
            words.push_back(std::move(w));
        }
        glued = nextGlued;
        i = j;
    }
    return words;
}

std::vector<NameReading> readMapFileName(const std::string& fileName) {
    const std::string name = std::filesystem::path(fileName).stem().string();
    const std::vector<NameWord> words = splitName(name);
    std::vector<NameReading> readings;

    // Set aside the neutral words at the end, and a green convention after a normal map's tag.
    std::size_t end = words.size();
    GreenHint green = GreenHint::None;
    while (end > 0) {
        if (isNeutralWord(words[end - 1].text)) {
            --end;
        } else if (green == GreenHint::None && end > 2 &&
                   greenHintOf(words[end - 2].text + words[end - 1].text) != GreenHint::None) {
            green = greenHintOf(words[end - 2].text + words[end - 1].text); // "Open" "GL"
            end -= 2;
        } else if (green == GreenHint::None && end > 1 &&
                   greenHintOf(words[end - 1].text) != GreenHint::None) {
            green = greenHintOf(words[end - 1].text);
            --end;
        } else {
            break;
        }
    }
    auto tagged = [&](std::size_t first, const MapTag* tag) {
        NameReading r;
        r.tag = tag;
        r.stem = stemBefore(name, words, first);
        r.glued = words[first].glued;
        r.green = isNormalRole(tag->role) ? green : GreenHint::None;
        if (tag->words == "normalgl")
            r.green = GreenHint::OpenGL;
        else if (tag->words == "normaldx")
            r.green = GreenHint::DirectX;
        r.tagText = name.substr(r.stem.size());
        if (green == GreenHint::None || isNormalRole(tag->role))
            readings.push_back(std::move(r));
    };
    if (end > 0) {
        auto [first, tag] = tagEndingAt(words, end);
        if (!tag && end > 1 && isGluedBitDepth(words[end - 1]))
            std::tie(first, tag) = tagEndingAt(words, end - 1);
        if (!tag && end > 1 && words[end - 1].text == "map") // "_diffuse_map", Unity's "_BumpMap"
            std::tie(first, tag) = tagEndingAt(words, end - 1);
        if (tag) {
            tagged(first, tag);
        } else {
            // A tag glued inside the last word ("stonez", "rocknormal"), longest first.
            const NameWord& last = words[end - 1];
            const MapTag* best = nullptr;
            for (const MapTag& t : mapTags()) {
                if (t.words.find(' ') == std::string_view::npos &&
                    last.text.size() > t.words.size() && last.text.ends_with(t.words) &&
                    std::all_of(t.words.begin(), t.words.end(), isLower) &&
                    (!best || t.words.size() > best->words.size()))
                    best = &t;
            }
            if (best) {
                NameReading r;
                r.tag = best;
                r.stem = name.substr(0, last.end - best->words.size());
                r.glued = true;
                r.green = isNormalRole(best->role) ? green : GreenHint::None;
                r.tagText = name.substr(r.stem.size());
                if (green == GreenHint::None || isNormalRole(best->role))
                    readings.push_back(std::move(r));
            }
        }
    }
    // Firm readings first.
    std::stable_sort(
        readings.begin(), readings.end(),
        [](const NameReading& a, const NameReading& b) { return !a.glued && b.glued; });
    NameReading plain;
    std::size_t plainEnd = words.size();
    while (plainEnd > 0 && isNeutralWord(words[plainEnd - 1].text) && !words[plainEnd - 1].glued)
        --plainEnd;
    plain.stem = plainEnd == 0 ? name : name.substr(0, words[plainEnd - 1].end);
    readings.push_back(std::move(plain));
    return readings;
}

} // namespace px
