#include "parallax/shader/ShaderGenerator.h"

#include "GlslUnit.h"
#include "ShaderBindings.h"
#include "ShaderFiles.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <unordered_map>

namespace px {

namespace {

constexpr int kLineBase = 10000; // shader files stay under 10000 lines

// The library every stage may draw from, in declaration order: the bindings, the trace kernels
// as shaders/trace/kernels.glsl lists them (the list the C++ kernels include), then the render
// files; the stage's main file comes last. Unreachable items are dropped.
const std::vector<std::string>& libraryFiles() {
    static const std::vector<std::string> files = [] {
        std::vector<std::string> f{"render/bindings.glsl"};
        std::string_view list = shader::embeddedFile("trace/kernels.glsl").value_or("");
        constexpr std::string_view kInclude = "#include \"";
        while (!list.empty()) {
            const std::string_view line = list.substr(0, list.find('\n'));
            list.remove_prefix(std::min(list.size(), line.size() + 1));
            if (line.starts_with(kInclude) && line.ends_with('"'))
                f.emplace_back(line.substr(kInclude.size(), line.size() - kInclude.size() - 1));
        }
        f.emplace_back("render/techniques.glsl");
        f.emplace_back("render/environment.glsl");
        f.emplace_back("render/lighting.glsl");
        return f;
    }();
    return files;
}

std::string macroName(std::string_view name) {
    std::string m;
    for (char c : name)
        m += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return m;
}

std::vector<std::string> definesFor(const VariantKey& k) {
    std::vector<std::string> d;
    d.push_back("PX_TECHNIQUE_" + macroName(info(k.technique).name));
    auto on = [&](bool bit, const char* name) {
        if (bit)
            d.emplace_back(name);
    };
    on(info(k.technique).parallax, "PX_HAS_PARALLAX");
    on(k.readsHeightMap(), "PX_HAS_HEIGHT_MAP");
    on(k.shadow, "PX_HAS_SHADOW");
    on(k.normalSource == NormalSource::Map, "PX_HAS_NORMAL_MAP");
    on(k.normalSource == NormalSource::HeightCentral || k.normalSource == NormalSource::HeightSobel,
       "PX_HAS_HEIGHT_NORMALS");
    on(k.normalSource == NormalSource::HeightSobel, "PX_HAS_SOBEL_NORMALS");
    on(k.albedoMap, "PX_HAS_ALBEDO_MAP");
    on(k.surfaceMap, "PX_HAS_SURFACE_MAP");
    on(k.wrap == WrapMode::Clamp, "PX_HAS_CLAMP_WRAP");
    on(k.lighting == LightingModel::MetallicRoughness, "PX_HAS_METALLIC_ROUGHNESS");
    on(k.tbn == TbnSource::Derivatives, "PX_HAS_DERIVATIVE_TBN");
    const bool surface =
        k.output == ShaderOutput::Surface || k.output == ShaderOutput::FootprintSurface;
    on(surface, "PX_HAS_SURFACE_OUTPUT");
    on(k.output == ShaderOutput::FootprintSurface, "PX_HAS_FOOTPRINT_REFERENCE");
    on(k.output == ShaderOutput::Trace, "PX_HAS_TRACE_OUTPUT");
    on(k.environment, "PX_HAS_ENVIRONMENT");
    on(k.flavour == KernelFlavour::Production && k.readsHeightMap(), "PX_HAS_HARDWARE_SAMPLING");
    // Derived: what the surface shader computes at all.
    const bool mesh = k.output != ShaderOutput::Trace;
    const bool parallax = info(k.technique).parallax;
    on(mesh && (parallax || k.normalSource != NormalSource::None), "PX_HAS_TANGENT_FRAME");
    on(mesh && (parallax || k.albedoMap || k.surfaceMap || k.normalSource != NormalSource::None ||
                surface),
       "PX_HAS_TEXTURE_COORDINATES");
    return d;
}

// What a stage's text depends on besides its defines and files.
struct StageOptions {
    std::string title;        // the header's first line: which variant and stage
    bool wrapRepeat = true;   // pxWrapRepeat, a constant of the variant
    bool precise = true;      // PX_PRECISE as `precise` (verify) or nothing (production)
    bool countFetches = true; // keep the fetch counter (only where an output writes it)
    std::string prelude;      // declarations after the header (a compute stage's layout)
};

// The production colour output writes no fetch count: its counting statements go (which leaves
// pxFetches unreachable, so it is not declared either). Newlines stay, so #line still holds.
// Removes what the pattern [ \t]*pxFetches\s*\+=\s*[^;\n]*;[ \t]* matches, scanned by hand:
// std::regex over every library file of every variant was most of the generator's time.
void removeFetchCounter(std::string& text) {
    constexpr std::string_view kCounter = "pxFetches";
    auto isBlank = [](char c) { return c == ' ' || c == '\t'; };
    auto skipSpace = [&](std::size_t i) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
            ++i;
        return i;
    };
    std::string out;
    std::size_t copied = 0; // text[0, copied) is decided: in `out`, or removed
    bool removed = false;
    for (std::size_t at = text.find(kCounter); at != std::string::npos;
         at = text.find(kCounter, at + 1)) {
        std::size_t end = skipSpace(at + kCounter.size());
        if (text.compare(end, 2, "+=") != 0)
            continue;
        end = text.find_first_of(";\n", skipSpace(end + 2));
        if (end == std::string::npos || text[end] != ';')
            continue;
        std::size_t begin = at;
        while (begin > copied && isBlank(text[begin - 1]))
            --begin;
        for (++end; end < text.size() && isBlank(text[end]);)
            ++end;
        out.append(text, copied, begin - copied);
        copied = end;
        removed = true;
        at = end - 1;
    }
    if (!removed)
        return;
    out.append(text, copied, std::string::npos);
    text = std::move(out);
}

// A file's items, split once per process for each text it preprocesses to. Splitting was most
// of a variant's generation, and across the thousands of variants each library file
// preprocesses to a few dozen distinct texts. Errors are not kept: the caller reports them.
using ItemList = std::shared_ptr<const std::vector<shader::GlslItem>>;
Result<ItemList> splitOnce(const std::string& text, int file, const std::string& path) {
    static std::mutex mutex;
    // By file, then by text (looked up without copying it).
    static std::map<std::pair<int, std::string>, std::unordered_map<std::string, ItemList>> split;
    static std::size_t count = 0;
    {
        const std::lock_guard lock(mutex);
        const std::unordered_map<std::string, ItemList>& texts = split[{file, path}];
        if (auto it = texts.find(text); it != texts.end())
            return it->second;
    }
    Result<std::vector<shader::GlslItem>> items = shader::splitItems(text, file, path);
    if (!items)
        return items.error();
    ItemList list = std::make_shared<const std::vector<shader::GlslItem>>(std::move(*items));
    const std::lock_guard lock(mutex);
    if (++count > 4096) { // bounded (all variants need ~1600); lists in use live on in `lists`
        split.clear();
        count = 1;
    }
    return split[{file, path}].emplace(text, std::move(list)).first->second;
}

// `inputs` receives the names of the stage inputs (`in` globals) the kept code reads.
Result<GeneratedShader> generateStage(const StageOptions& options,
                                      const std::vector<std::string>& defines,
                                      const std::vector<std::string>& files,
                                      std::set<std::string>* inputs = nullptr) {
    GeneratedShader s;
    s.defines = defines;
    s.sources.push_back("(generated header)");
    std::set<std::string> defineSet(defines.begin(), defines.end());
    defineSet.insert("PX_PRECISE"); // emitted as `precise` below
    std::vector<ItemList> lists;    // keeps the cached lists alive while `items` points into them
    std::vector<const shader::GlslItem*> items;
    for (std::size_t k = 0; k < files.size(); ++k) {
        const std::string path = "shaders/" + files[k];
        const std::optional<std::string_view> text = shader::embeddedFile(files[k]);
        if (!text)
            return Error{path + ": not among the embedded shader files (rebuild after adding it)"};
        Result<std::string> pre = shader::preprocess(*text, defineSet, path);
        if (!pre)
            return pre.error();
        if (!options.countFetches)
            removeFetchCounter(*pre);
        Result<ItemList> split = splitOnce(*pre, static_cast<int>(k + 1), path);
        if (!split)
            return split.error();
        for (const shader::GlslItem& item : **split)
            items.push_back(&item);
        lists.push_back(std::move(*split));
        s.sources.push_back(path);
    }
    std::set<std::string> external;
    const std::vector<const shader::GlslItem*> kept =
        shader::reachableItems(items, {"main"}, external);
    if (external.count("main"))
        return Error{"shaders/" + files.back() + ": no main()"};
    if (inputs) {
        for (const shader::GlslItem* item : kept) {
            // Skip the item's leading comment lines.
            std::size_t code = item->text.find_first_not_of(" \t\n");
            while (code != std::string::npos && item->text.compare(code, 2, "//") == 0)
                code = item->text.find_first_not_of(" \t\n", item->text.find('\n', code));
            if (code != std::string::npos && item->text.compare(code, 3, "in ") == 0)
                inputs->insert(item->names.begin(), item->names.end());
        }
    }

    std::string text = "#version 430 core\n";
    text += "// Parallax Studio " + options.title +
            ".\n// Generated from shaders/ by core/src/shader/ShaderGenerator.cpp: only the "
            "code this variant reaches.\n// #line L S: source S, line L - S * " +
            std::to_string(kLineBase) +
            " of it (the line carries the source: Mesa reports none):\n";
    std::set<int> used;
    for (const shader::GlslItem* item : kept)
        used.insert(item->file);
    for (int k : used)
        text += "//   " + std::to_string(k) + " " + s.sources[static_cast<std::size_t>(k)] + "\n";
    for (const std::string& d : defines)
        text += "#define " + d + " 1\n";
    if (external.count("PX_PRECISE"))
        text += options.precise ? "#define PX_PRECISE precise\n" : "#define PX_PRECISE\n";
    for (const shader::Binding& b : shader::bindings()) {
        if (external.count(b.name)) {
            text += shader::declaration(b) + "\n";
            s.uniforms.push_back({b.name, b.type, b.unit});
        }
    }
    if (external.count("pxWrapRepeat"))
        text += std::string("const bool pxWrapRepeat = ") +
                (options.wrapRepeat ? "true" : "false") + ";\n";
    text += options.prelude;

    int file = 0;
    int nextLine = -1;
    for (const shader::GlslItem* item : kept) {
        const int gap = item->firstLine - nextLine;
        if (item->file == file && gap > 0 && gap <= 3)
            text.append(static_cast<std::size_t>(gap), '\n'); // keep the file's blank lines
        else if (item->file != file || gap != 0)
            text += "#line " + std::to_string(kLineBase * item->file + item->firstLine) + " " +
                    std::to_string(item->file) + "\n";
        text += item->text;
        file = item->file;
        nextLine = item->firstLine +
                   static_cast<int>(std::count(item->text.begin(), item->text.end(), '\n'));
    }
    s.text = std::move(text);
    return s;
}

bool parseNumber(const std::string& digits, unsigned long& value) {
    const char* end = digits.data() + digits.size();
    const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
    return ec == std::errc() && ptr == end;
}

} // namespace

Result<GeneratedProgram> generateProgram(const VariantKey& requested) {
    const VariantKey key = canonical(requested);
    if (Status valid = key.validate(); !valid)
        return valid.error();
    const bool trace = key.output == ShaderOutput::Trace;
    const bool production = key.flavour == KernelFlavour::Production;

    GeneratedProgram program;
    program.key = key;
    // The fragment stage first: the vertex stage writes only the outputs it reads.
    std::vector<std::string> files = libraryFiles();
    files.push_back(trace ? "render/trace.frag.glsl" : "render/surface.frag.glsl");
    char keyHex[16];
    std::snprintf(keyHex, sizeof keyHex, "0x%04x", key.bits());
    StageOptions fragmentOptions;
    fragmentOptions.title =
        "shader variant " + key.name() + " (key " + keyHex + "), fragment stage";
    fragmentOptions.wrapRepeat = key.wrap == WrapMode::Repeat;
    fragmentOptions.precise = !production;
    fragmentOptions.countFetches = !production || key.output != ShaderOutput::Color;
    std::set<std::string> inputs;
    Result<GeneratedShader> fragment =
        generateStage(fragmentOptions, definesFor(key), files, &inputs);
    if (!fragment)
        return fragment.error();

    // The vertex stage reads no feature of the key, only which outputs the fragment stage keeps
    // (Filament's per-stage filter): its key, name and text are those alone.
    program.vertexKey.trace = trace;
    program.vertexKey.outputs.assign(inputs.begin(), inputs.end());
    std::vector<std::string> vertexDefines;
    vertexDefines.reserve(inputs.size());
    for (const std::string& input : inputs)
        vertexDefines.push_back("PX_FRAGMENT_READS_" + macroName(input));
    StageOptions vertexOptions;
    vertexOptions.title = "vertex variant " + program.vertexKey.name() + ", vertex stage";
    Result<GeneratedShader> vertex =
        generateStage(vertexOptions, vertexDefines,
                      {trace ? "render/trace.vert.glsl" : "render/surface.vert.glsl"});
    if (!vertex)
        return vertex.error();
    program.vertex = std::move(*vertex);
    program.fragment = std::move(*fragment);
    return program;
}

Result<GeneratedProgram> generateBackgroundProgram() {
    GeneratedProgram program;
    StageOptions fragmentOptions;
    fragmentOptions.title = "environment background, fragment stage";
    fragmentOptions.countFetches = false;
    Result<GeneratedShader> fragment = generateStage(
        fragmentOptions, {},
        {"render/environment.glsl", "render/lighting.glsl", "render/background.frag.glsl"});
    if (!fragment)
        return fragment.error();
    StageOptions vertexOptions;
    vertexOptions.title = "environment background, vertex stage";
    Result<GeneratedShader> vertex =
        generateStage(vertexOptions, {}, {"render/background.vert.glsl"});
    if (!vertex)
        return vertex.error();
    program.vertex = std::move(*vertex);
    program.fragment = std::move(*fragment);
    return program;
}

Result<GeneratedShader> generateBakeShader(BakeShaderKind kind, WrapMode wrap, int localSize) {
    // The GPU's bindings first (the kernels call them), then the kernels as kernels.glsl lists
    // them (the list the C++ compilation includes), then the kind's main().
    std::vector<std::string> files{"bake/gpu/bindings.glsl"};
    std::string_view list = shader::embeddedFile("bake/kernels.glsl").value_or("");
    constexpr std::string_view kInclude = "#include \"";
    while (!list.empty()) {
        const std::string_view line = list.substr(0, list.find('\n'));
        list.remove_prefix(std::min(list.size(), line.size() + 1));
        if (line.starts_with(kInclude) && line.ends_with('"'))
            files.emplace_back(line.substr(kInclude.size(), line.size() - kInclude.size() - 1));
    }
    const bool relaxed = kind == BakeShaderKind::Relaxed;
    files.emplace_back(relaxed ? "bake/gpu/relaxed.comp.glsl" : "bake/gpu/quick.comp.glsl");
    StageOptions options;
    options.title = std::string(relaxed ? "relaxed" : "quick") + " cone bake (" +
                    std::string(toString(wrap)) + "), compute stage";
    options.countFetches = false;
    options.prelude =
        "layout(local_size_x = " + std::to_string(localSize) +
        ") in;\nconst bool pxBakeRepeat = " + (wrap == WrapMode::Repeat ? "true" : "false") + ";\n";
    return generateStage(options, {}, files);
}

std::string VertexKey::name() const {
    std::string n = trace ? "trace" : "mesh";
    for (const std::string& output : outputs)
        n += "+" + output;
    return n;
}

std::string mapCompilerLog(std::string_view log, const std::vector<std::string>& sources) {
    // Mesa "0:12(5):", glslang "ERROR: 0:12:", NVIDIA "0(12) :".
    static const std::regex position(R"((^|[^0-9A-Za-z_.])(\d+)(:(\d+)|\((\d+)\)))");
    std::string out;
    const std::string text(log);
    std::size_t last = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), position);
         it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        // A driver's log is untrusted text: a number too long for the type is left as it is
        // (std::from_chars reports it; std::stoul would throw through the core).
        unsigned long source = 0, line = 0;
        const bool parsed = parseNumber(m[2].str(), source) &&
                            parseNumber(m[4].matched ? m[4].str() : m[5].str(), line);
        if (parsed && line >= static_cast<unsigned long>(kLineBase)) {
            source = line / kLineBase;
            line %= kLineBase;
        }
        out.append(text, last, m.position(0) - last);
        if (parsed && source < sources.size())
            out += m[1].str() + sources[source] + ":" + std::to_string(line);
        else
            out += m[0].str();
        last = m.position(0) + m.length(0);
    }
    out.append(text, last, std::string::npos);
    return out;
}

} // namespace px
