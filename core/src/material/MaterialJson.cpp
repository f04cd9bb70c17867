// The material file's JSON: reading with a message per problem, writing every field.

#include "MaterialLimits.h"
#include "MaterialText.h"
#include "io/ShortestDecimal.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

namespace px {

using namespace material;
using nlohmann::json;

namespace {

// What a value is, for "got ..." (long values shortened).
std::string describe(const json& value) {
    if (value.is_object())
        return "an object";
    if (value.is_array())
        return "an array";
    std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
    if (text.size() > 40)
        text = text.substr(0, 37) + "...";
    return text;
}

std::string quotedList(std::span<const std::string_view> names) {
    std::string text;
    for (std::string_view name : names)
        text += (text.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    return text;
}

// Reads one JSON document into a Material, collecting a problem per bad value. A value with a
// problem keeps its default so the rest can still be checked.
class Reader {
public:
    std::vector<MaterialProblem> problems;

    void add(std::string pointer, std::string message) {
        problems.push_back({std::move(pointer), std::move(message)});
    }

    // `value` must be an object holding only `known` keys.
    bool object(const json& value, const std::string& pointer,
                std::initializer_list<std::string_view> known) {
        if (!value.is_object()) {
            add(pointer, "expected an object, got " + describe(value));
            return false;
        }
        for (const auto& [key, item] : value.items()) {
            if (std::find(known.begin(), known.end(), key) == known.end()) {
                std::string names;
                for (std::string_view k : known)
                    names += (names.empty() ? "" : ", ") + std::string(k);
                add(pointer + "/" + escapeKey(key), "unknown key (known here: " + names + ")");
            }
        }
        return true;
    }

    const json* member(const json& object, const char* key) {
        auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    void string(const json& object, const std::string& pointer, const char* key, std::string& out) {
        if (const json* v = member(object, key)) {
            if (v->is_string())
                out = v->get<std::string>();
            else
                add(pointer + "/" + key, "expected a string, got " + describe(*v));
        }
    }

    void boolean(const json& object, const std::string& pointer, const char* key, bool& out) {
        if (const json* v = member(object, key)) {
            if (v->is_boolean())
                out = v->get<bool>();
            else
                add(pointer + "/" + key, "expected true or false, got " + describe(*v));
        }
    }

    void number(const json& object, const std::string& pointer, const char* key, NumberRange range,
                float& out) {
        const json* v = member(object, key);
        if (!v)
            return;
        const double d = v->is_number() ? v->get<double>() : NAN;
        if (!std::isfinite(d) || d < range.lo || d > range.hi)
            add(pointer + "/" + key, expectedNumber(range) + ", got " + describe(*v));
        else
            out = static_cast<float>(d);
    }

    void integer(const json& object, const std::string& pointer, const char* key, IntRange range,
                 int& out) {
        const json* v = member(object, key);
        if (!v)
            return;
        // 8.0 is an integer; 8.5, "8" and 1e30 are not.
        const double d = v->is_number() ? v->get<double>() : NAN;
        if (!std::isfinite(d) || d != std::floor(d) || d < range.lo || d > range.hi)
            add(pointer + "/" + key, expectedInteger(range) + ", got " + describe(*v));
        else
            out = static_cast<int>(d);
    }

    // [lo, hi]: two finite numbers (validateMaterial checks lo < hi).
    void range(const json& object, const std::string& pointer, const char* key,
               std::optional<HeightRange>& out) {
        const json* v = member(object, key);
        if (!v)
            return;
        auto finite = [](const json& n) {
            return n.is_number() && std::isfinite(n.get<double>()) &&
                   std::abs(n.get<double>()) <= std::numeric_limits<float>::max();
        };
        if (v->is_array() && v->size() == 2 && finite((*v)[0]) && finite((*v)[1]))
            out = HeightRange{(*v)[0].get<float>(), (*v)[1].get<float>()};
        else
            add(pointer + "/" + key,
                "expected [lo, hi], the file values for heights 0 and 1, got " + describe(*v));
    }

    template <typename Enum, typename Parse>
    void enumeration(const json& object, const std::string& pointer, const char* key, Parse parse,
                     std::span<const std::string_view> names, Enum& out) {
        const json* v = member(object, key);
        if (!v)
            return;
        std::optional<Enum> parsed;
        if (v->is_string())
            parsed = parse(v->get<std::string>());
        if (parsed)
            out = *parsed;
        else
            add(pointer + "/" + key,
                "expected one of " + quotedList(names) + ", got " + describe(*v));
    }

    // RFC 6901: '~' and '/' in a key are escaped in a JSON pointer.
    static std::string escapeKey(const std::string& key) {
        std::string out;
        for (char c : key)
            out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        return out;
    }
};

std::vector<std::string_view> techniqueNames() {
    std::vector<std::string_view> names;
    for (const TechniqueInfo& t : allTechniques())
        names.push_back(t.name);
    return names;
}

// "format" and "version": anything else is only read once these say it is our file and version.
bool readHeader(const json& root, Reader& r) {
    auto format = root.find("format");
    if (format == root.end() || !format->is_string() || *format != kMaterialFormat) {
        r.add("/format", "expected \"" + std::string(kMaterialFormat) + "\", got " +
                             (format == root.end() ? std::string("nothing") : describe(*format)) +
                             ": this is not a Parallax Studio material");
        return false;
    }
    auto version = root.find("version");
    if (version == root.end() || !version->is_number_integer()) {
        r.add("/version",
              "expected the format version (an integer), got " +
                  (version == root.end() ? std::string("nothing") : describe(*version)));
        return false;
    }
    // A negative version is no version of ours; a larger one is a newer file, refused.
    const bool newer =
        version->is_number_unsigned()
            ? version->get<unsigned long long>() > static_cast<unsigned long long>(kMaterialVersion)
            : version->get<long long>() > kMaterialVersion;
    if (newer) {
        r.add("/version", "version " + describe(*version) +
                              " was written by a newer Parallax Studio; this one reads version " +
                              std::to_string(kMaterialVersion) +
                              " only (update Parallax Studio to open it)");
        return false;
    }
    if (version->get<long long>() != kMaterialVersion) {
        r.add("/version",
              "expected " + std::to_string(kMaterialVersion) + ", got " + describe(*version));
        return false;
    }
    return true;
}

void readBody(const json& root, Reader& r, Material& m) {
    r.object(root, "",
             {"format", "version", "name", "maps", "surface", "height", "wrap", "tiling",
              "technique", "normal", "shadow", "lighting", "light"});
    r.string(root, "", "name", m.name);
    if (const json* maps = r.member(root, "maps");
        maps && r.object(*maps, "/maps",
                         {"albedo", "height", "normal", "cone", "relaxedCone", "ao", "roughness",
                          "metallic", "specular"})) {
        MaterialMaps& p = m.maps;
        for (auto [key, field] : {std::pair{"albedo", &p.albedo},
                                  {"height", &p.height},
                                  {"normal", &p.normal},
                                  {"cone", &p.cone},
                                  {"relaxedCone", &p.relaxedCone},
                                  {"ao", &p.ao},
                                  {"roughness", &p.roughness},
                                  {"metallic", &p.metallic},
                                  {"specular", &p.specular}}) {
            if (const json* v = r.member(*maps, key); v && v->is_null())
                continue; // null = absent
            r.string(*maps, "/maps", key, *field);
        }
    }
    if (const json* s = r.member(root, "surface");
        s && r.object(*s, "/surface",
                      {"aoChannel", "roughnessChannel", "metallicChannel", "roughnessIsGloss"})) {
        r.enumeration(*s, "/surface", "aoChannel", parseHeightChannel, heightChannelNames(),
                      m.surface.ao);
        r.enumeration(*s, "/surface", "roughnessChannel", parseHeightChannel, heightChannelNames(),
                      m.surface.roughness);
        r.enumeration(*s, "/surface", "metallicChannel", parseHeightChannel, heightChannelNames(),
                      m.surface.metallic);
        r.boolean(*s, "/surface", "roughnessIsGloss", m.surface.gloss);
    }
    if (const json* h = r.member(root, "height");
        h && r.object(*h, "/height", {"channel", "invert", "scale", "range", "derivedFrom"})) {
        r.enumeration(*h, "/height", "channel", parseHeightChannel, heightChannelNames(),
                      m.heightChannel);
        r.boolean(*h, "/height", "invert", m.heightIsDepth);
        r.number(*h, "/height", "scale", kHeightScale, m.heightScale);
        r.string(*h, "/height", "derivedFrom", m.heightDerivedFrom);
        r.range(*h, "/height", "range", m.heightRange);
    }
    static constexpr std::string_view kWraps[] = {"repeat", "clamp"};
    r.enumeration(root, "", "wrap", parseWrapMode, kWraps, m.wrap);
    r.number(root, "", "tiling", kTiling, m.tiling);

    if (const json* t = r.member(root, "technique");
        t && r.object(*t, "/technique",
                      {"name", "minLayers", "maxLayers", "binarySteps", "secantSteps", "maxSteps",
                       "budget", "maxPolar", "budgetPixels", "texelsPerPixel"})) {
        std::vector<std::string_view> names = techniqueNames();
        names.push_back("auto");
        if (const json* n = r.member(*t, "name"); n && n->is_string() && *n == "auto") {
            AutoQuality q;
            r.number(*t, "/technique", "budget", kAutoBudget, q.budget);
            r.number(*t, "/technique", "maxPolar", kAutoMaxPolar, q.maxPolar);
            const bool pixels = r.member(*t, "budgetPixels"),
                       density = r.member(*t, "texelsPerPixel");
            if (pixels != density)
                r.add("/technique", "budgetPixels and texelsPerPixel go together (a budget in "
                                    "pixels needs the texels one pixel covers)");
            else if (pixels && r.member(*t, "budget"))
                r.add("/technique", "give budget (texels) or budgetPixels, not both");
            if (pixels && density) {
                float p = 0.0f, d = 0.0f;
                const std::size_t before = r.problems.size();
                r.number(*t, "/technique", "budgetPixels", kAutoBudget, p);
                r.number(*t, "/technique", "texelsPerPixel", kTexelsPerPixel, d);
                if (r.problems.size() == before) {
                    q.budgetPixels = p;
                    q.texelsPerPixel = d;
                }
            }
            m.autoQuality = q;
        } else {
            r.enumeration(*t, "/technique", "name", parseTechnique, names, m.technique);
        }
        m.params = info(m.technique).defaults; // unset parameters: this technique's defaults
        r.integer(*t, "/technique", "minLayers", kLayers, m.params.minLayers);
        r.integer(*t, "/technique", "maxLayers", kLayers, m.params.maxLayers);
        r.integer(*t, "/technique", "binarySteps", kRefine, m.params.binarySteps);
        r.integer(*t, "/technique", "secantSteps", kRefine, m.params.secantSteps);
        r.integer(*t, "/technique", "maxSteps", kSteps, m.params.maxSteps);
    }
    if (const json* n = r.member(root, "normal");
        n && r.object(*n, "/normal", {"source", "green"})) {
        r.enumeration(*n, "/normal", "source", parseNormalSource, normalSourceNames(),
                      m.normalSource);
        r.enumeration(*n, "/normal", "green", parseNormalGreen, normalGreenNames(), m.normalGreen);
    }
    if (const json* s = r.member(root, "shadow");
        s && r.object(*s, "/shadow", {"enabled", "softness"})) {
        r.boolean(*s, "/shadow", "enabled", m.selfShadow);
        r.number(*s, "/shadow", "softness", kUnit, m.shadowSoftness);
    }
    if (const json* l = r.member(root, "lighting");
        l &&
        r.object(*l, "/lighting", {"model", "roughness", "metallic", "specular", "shininess"})) {
        r.enumeration(*l, "/lighting", "model", parseLightingModel, lightingModelNames(),
                      m.lighting);
        r.number(*l, "/lighting", "roughness", kUnit, m.roughness);
        r.number(*l, "/lighting", "metallic", kUnit, m.metallic);
        r.number(*l, "/lighting", "specular", kUnit, m.specular);
        r.number(*l, "/lighting", "shininess", kShininess, m.shininess);
    }
    if (const json* l = r.member(root, "light");
        l && r.object(*l, "/light", {"azimuth", "elevation"})) {
        LightDirection light;
        r.number(*l, "/light", "azimuth", kLightAzimuth, light.azimuthDeg);
        r.number(*l, "/light", "elevation", kLightElevation, light.elevationDeg);
        m.light = light;
    }
}

void read(const json& root, Reader& reader, Material& material, MaterialCheck check);

} // namespace

Result<Material> parseMaterial(std::string_view text, const std::string& source,
                               MaterialCheck check) {
    json root;
    // A key given twice in one object: nlohmann keeps the last, another reader may keep the first,
    // so which value the material has would depend on the program. Refused, with where.
    // Each open object or array keeps only its own key; the pointer is spelled out only for a
    // duplicate (a copy per level costs the square of the depth: 15 GB for 100 000 levels).
    struct Frame {
        bool object = false;
        std::string lastKey;
        std::set<std::string> keys;
    };
    std::vector<Frame> frames;
    std::string duplicate;
    const auto pointerTo = [&frames](const std::string& key) {
        std::string pointer;
        for (std::size_t i = 0; i + 1 < frames.size(); ++i)
            pointer += "/" + (frames[i].object ? Reader::escapeKey(frames[i].lastKey) : "[]");
        return pointer + "/" + Reader::escapeKey(key);
    };
    const json::parser_callback_t noDuplicates = [&](int, json::parse_event_t event, json& parsed) {
        if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start)
            frames.push_back({event == json::parse_event_t::object_start, {}, {}});
        else if (event == json::parse_event_t::object_end ||
                 event == json::parse_event_t::array_end)
            frames.pop_back();
        else if (event == json::parse_event_t::key && !frames.empty()) {
            Frame& f = frames.back();
            f.lastKey = parsed.get<std::string>();
            if (!f.keys.insert(f.lastKey).second && duplicate.empty())
                duplicate = pointerTo(f.lastKey);
        }
        return true;
    };
    try {
        root = json::parse(text.begin(), text.end(), noDuplicates);
    } catch (const json::exception& e) { // syntax errors, and numbers like 1e999
        std::string what = e.what();
        if (const auto close = what.find("] ");
            what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
            what = what.substr(close + 2);
        return fileError(source, "not valid JSON (" + what + ")");
    }
    if (!duplicate.empty())
        return fileError(source, duplicate + ": the key appears twice in one object (which value "
                                             "counts would depend on the program reading it); "
                                             "keep one");
    Reader reader;
    Material material;
    try {
        read(root, reader, material, check);
    } catch (const json::exception& e) { // not expected: every access checks its type first
        return fileError(source, std::string("cannot read the material (") + e.what() + ")");
    }
    if (!reader.problems.empty())
        return Error{formatProblems(reader.problems, source)};
    return material;
}

namespace {

void read(const json& root, Reader& reader, Material& material, MaterialCheck check) {
    if (!root.is_object()) {
        reader.add("",
                   "expected a JSON object (a Parallax Studio material), got " + describe(root));
    } else if (readHeader(root, reader)) {
        readBody(root, reader, material);
        // Value rules across fields; a pointer the reader already reported is not reported twice.
        std::set<std::string> reported;
        for (const MaterialProblem& p : reader.problems)
            reported.insert(p.pointer);
        for (MaterialProblem& p : validateMaterial(material, check)) {
            if (!reported.count(p.pointer))
                reader.problems.push_back(std::move(p));
        }
    }
}

} // namespace

std::string materialToJson(const Material& m) {
    nlohmann::ordered_json root;
    root["format"] = kMaterialFormat;
    root["version"] = kMaterialVersion;
    root["name"] = m.name;
    nlohmann::ordered_json maps = nlohmann::ordered_json::object();
    for (auto [key, value] : {std::pair{"albedo", &m.maps.albedo},
                              {"height", &m.maps.height},
                              {"normal", &m.maps.normal},
                              {"cone", &m.maps.cone},
                              {"relaxedCone", &m.maps.relaxedCone},
                              {"ao", &m.maps.ao},
                              {"roughness", &m.maps.roughness},
                              {"metallic", &m.maps.metallic},
                              {"specular", &m.maps.specular}}) {
        if (!value->empty())
            maps[key] = *value;
    }
    root["maps"] = maps;
    // Written only where a packed file asks for it, so ordinary materials read as before.
    if (m.surface != SurfaceChannels{})
        root["surface"] = {{"aoChannel", toString(m.surface.ao)},
                           {"roughnessChannel", toString(m.surface.roughness)},
                           {"metallicChannel", toString(m.surface.metallic)},
                           {"roughnessIsGloss", m.surface.gloss}};
    root["height"] = {{"channel", toString(m.heightChannel)},
                      {"invert", m.heightIsDepth},
                      {"scale", shortestDecimal(m.heightScale)}};
    if (m.heightRange) // written only for a file read by its range, so others read as before
        root["height"]["range"] = {shortestDecimal(m.heightRange->lo),
                                   shortestDecimal(m.heightRange->hi)};
    if (!m.heightDerivedFrom.empty())
        root["height"]["derivedFrom"] = m.heightDerivedFrom;
    root["wrap"] = toString(m.wrap);
    root["tiling"] = shortestDecimal(m.tiling);
    if (m.autoQuality && m.autoQuality->budgetPixels && m.autoQuality->texelsPerPixel)
        root["technique"] = {{"name", "auto"},
                             {"budgetPixels", shortestDecimal(*m.autoQuality->budgetPixels)},
                             {"texelsPerPixel", shortestDecimal(*m.autoQuality->texelsPerPixel)},
                             {"maxPolar", shortestDecimal(m.autoQuality->maxPolar)}};
    else if (m.autoQuality)
        root["technique"] = {{"name", "auto"},
                             {"budget", shortestDecimal(m.autoQuality->budget)},
                             {"maxPolar", shortestDecimal(m.autoQuality->maxPolar)}};
    else
        root["technique"] = {
            {"name", info(m.technique).name},      {"minLayers", m.params.minLayers},
            {"maxLayers", m.params.maxLayers},     {"binarySteps", m.params.binarySteps},
            {"secantSteps", m.params.secantSteps}, {"maxSteps", m.params.maxSteps}};
    root["normal"] = {{"source", toString(m.normalSource)}, {"green", toString(m.normalGreen)}};
    root["shadow"] = {{"enabled", m.selfShadow}, {"softness", shortestDecimal(m.shadowSoftness)}};
    root["lighting"] = {{"model", toString(m.lighting)},
                        {"roughness", shortestDecimal(m.roughness)},
                        {"metallic", shortestDecimal(m.metallic)},
                        {"specular", shortestDecimal(m.specular)},
                        {"shininess", shortestDecimal(m.shininess)}};
    if (m.light) // written only where the editor saved one, so other files read as before
        root["light"] = {{"azimuth", shortestDecimal(m.light->azimuthDeg)},
                         {"elevation", shortestDecimal(m.light->elevationDeg)}};
    return root.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

} // namespace px
