// Technique "auto" in the material file (read, written, refused when out of range), resolved on the
// material's own height map, and exported: the package carries only the maps and shader the chosen
// setting reads, Godot the layer counts of its own march.

#include "parallax/eval/AutoTechnique.h"

#include "parallax/export/Exporter.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace px;

class AutoTechniqueTest : public QObject {
    Q_OBJECT

private slots:
    void init() { clearRecommendationCache(); }
    void readAndWrittenInTheMaterialFile();
    void outOfRangeIsRefused();
    void pixelBudget();
    void resolvesToTheRecommendation();
    void exportCarriesTheChoice();
    void exportsKeepTheirConeBakes();
};

namespace {

const char* kAutoMaterial = R"({"format": "parallax-studio-material", "version": 1,
  "maps": {"height": "stones_height.png"},
  "technique": {"name": "auto", "budget": 0.25, "maxPolar": 70}})";

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

void AutoTechniqueTest::readAndWrittenInTheMaterialFile() {
    Result<Material> m = parseMaterial(kAutoMaterial, "auto.json");
    QVERIFY2(m.ok(), m.ok() ? "" : m.error().message.c_str());
    QVERIFY(m->autoQuality.has_value());
    QCOMPARE(m->autoQuality->budget, 0.25f);
    QCOMPARE(m->autoQuality->maxPolar, 70.0f);
    const std::string json = materialToJson(*m);
    QVERIFY2(json.find("\"technique\": {\n    \"name\": \"auto\",\n    \"budget\": 0.25,\n    "
                       "\"maxPolar\": 70.0\n  }") != std::string::npos,
             json.c_str());
    Result<Material> again = parseMaterial(json, "again.json");
    QVERIFY(again.ok() && again->autoQuality && again->autoQuality->budget == 0.25f);
    // A named technique has no auto settings.
    Result<Material> pom = parseMaterial(
        R"({"format": "parallax-studio-material", "version": 1, "maps": {"height": "h.png"},
            "technique": {"name": "pom"}})",
        "pom.json");
    QVERIFY(pom.ok() && !pom->autoQuality);
}

void AutoTechniqueTest::outOfRangeIsRefused() {
    Result<Material> m = parseMaterial(
        R"({"format": "parallax-studio-material", "version": 1, "maps": {"height": "h.png"},
            "technique": {"name": "auto", "maxPolar": 95, "budget": -1}})",
        "bad.json");
    QVERIFY(!m.ok());
    const QString message = QString::fromStdString(m.error().message);
    QVERIFY2(message.contains("bad.json: /technique/budget: expected a number") &&
                 message.contains("bad.json: /technique/maxPolar: expected a number"),
             qPrintable(message));
}

// A budget in pixels: budgetPixels x texelsPerPixel texels, written back as given, both or neither.
void AutoTechniqueTest::pixelBudget() {
    const char* text = R"({"format": "parallax-studio-material", "version": 1,
      "maps": {"height": "h.png"},
      "technique": {"name": "auto", "budgetPixels": 0.5, "texelsPerPixel": 0.5, "maxPolar": 70}})";
    Result<Material> m = parseMaterial(text, "px.json");
    QVERIFY2(m.ok(), m.ok() ? "" : m.error().message.c_str());
    QVERIFY(m->autoQuality && m->autoQuality->budgetPixels && m->autoQuality->texelsPerPixel);
    QCOMPARE(m->autoQuality->budgetTexels(), 0.25f);
    const std::string json = materialToJson(*m);
    QVERIFY2(json.find("\"budgetPixels\": 0.5,\n    \"texelsPerPixel\": 0.5") !=
                     std::string::npos &&
                 json.find("\"budget\":") == std::string::npos,
             json.c_str());
    Result<Material> again = parseMaterial(json, "again.json");
    QVERIFY(again.ok() && again->autoQuality && again->autoQuality->budgetTexels() == 0.25f);

    // Resolved as the same budget in texels would be, and the note says both.
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 64, 64, 4);
    Result<ResolvedAuto> byPixels = resolveAutoTechnique(*m, field, {}, {}, "px.json");
    Result<Material> texels = parseMaterial(kAutoMaterial, "auto.json"); // budget 0.25, 70 degrees
    QVERIFY(byPixels.ok() && texels.ok());
    Result<ResolvedAuto> byTexels = resolveAutoTechnique(*texels, field, {}, {}, "auto.json");
    QVERIFY(byTexels.ok());
    QCOMPARE(byPixels->material.technique, byTexels->material.technique);
    QCOMPARE(byPixels->material.params.maxSteps, byTexels->material.params.maxSteps);
    QCOMPARE(byPixels->material.params.maxLayers, byTexels->material.params.maxLayers);
    QVERIFY2(byPixels->note.find("p99 <= 0.25 texel (0.5 pixel at 0.5 texels per pixel) up to 70 "
                                 "degrees") != std::string::npos,
             byPixels->note.c_str());

    // One without the other, both budgets, a density of 0: refused, each saying why.
    const struct {
        const char* technique;
        const char* expected;
    } bad[] = {
        {R"({"name": "auto", "budgetPixels": 1})", "budgetPixels and texelsPerPixel go together"},
        {R"({"name": "auto", "texelsPerPixel": 2})", "budgetPixels and texelsPerPixel go together"},
        {R"({"name": "auto", "budget": 1, "budgetPixels": 1, "texelsPerPixel": 2})",
         "give budget (texels) or budgetPixels, not both"},
        {R"({"name": "auto", "budgetPixels": 1, "texelsPerPixel": 0})",
         "/technique/texelsPerPixel: expected a number"},
    };
    for (const auto& b : bad) {
        const std::string doc = std::string(R"({"format": "parallax-studio-material", "version": 1,
          "maps": {"height": "h.png"}, "technique": )") +
                                b.technique + "}";
        Result<Material> refused = parseMaterial(doc, "bad.json");
        QVERIFY2(!refused.ok(), b.technique);
        QVERIFY2(refused.error().message.find(b.expected) != std::string::npos,
                 refused.error().message.c_str());
    }
}

void AutoTechniqueTest::resolvesToTheRecommendation() {
    Result<Material> m = parseMaterial(kAutoMaterial, "auto.json");
    QVERIFY(m.ok());
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 64, 64, 4);
    Result<ResolvedAuto> resolved =
        resolveAutoTechnique(*m, field, {}, {}, "auto.json", EngineMarch::Godot);
    QVERIFY2(resolved.ok(), resolved.ok() ? "" : resolved.error().message.c_str());
    QVERIFY(!resolved->material.autoQuality);

    RecommendConfig config;
    config.field = std::make_shared<HeightField>(field);
    config.scale = m->heightScale;
    config.maxPolarDeg = 70.0;
    config.budget.texels = 0.25;
    Result<Recommendation> r = recommend(config);
    QVERIFY(r.ok() && r->found);
    QCOMPARE(resolved->material.technique, r->chosen.setting.technique);
    QCOMPARE(resolved->material.params.maxSteps, r->chosen.setting.params.maxSteps);
    QCOMPARE(resolved->material.params.maxLayers, r->chosen.setting.params.maxLayers);
    QVERIFY(QString::fromStdString(resolved->note)
                .startsWith("technique auto resolved to " +
                            QString::fromUtf8(info(r->chosen.setting.technique).name.data())));
    QVERIFY(resolved->engineLayers && resolved->engineLayers->found);

    // A material that names its technique is left as it is.
    Material pom;
    Result<ResolvedAuto> same = resolveAutoTechnique(pom, field, {}, {}, "pom.json");
    QVERIFY(same.ok() && same->note.empty() && same->material.technique == Technique::Pom);
}

void AutoTechniqueTest::exportCarriesTheChoice() {
    QTemporaryDir dir;
    const std::filesystem::path root = dir.path().toStdString();
    ImageWriteOptions o;
    o.format = PixelFormat::UInt16;
    QVERIFY(writeImage((root / "stones_height.png").string(),
                       makeProceduralMap(ProceduralMap::Stones, 64, 64, 4).toImage(), o)
                .ok());
    { std::ofstream(root / "auto.json") << kAutoMaterial; }
    Result<Material> m = loadMaterial((root / "auto.json").string());
    QVERIFY(m.ok());

    ExportOptions options;
    options.format = ExportFormat::Godot;
    options.outDir = (root / "godot").string();
    Result<ExportResult> godot = exportMaterial(*m, (root / "auto.json").string(), options);
    QVERIFY2(godot.ok(), godot.ok() ? "" : godot.error().message.c_str());
    QVERIFY(!godot->notes.empty() &&
            QString::fromStdString(godot->notes.front()).startsWith("technique auto resolved to"));
    const std::string tres = readText(root / "godot" / "untitled.tres");
    Result<ResolvedAuto> resolved =
        resolveAutoTechnique(*m, makeProceduralMap(ProceduralMap::Stones, 64, 64, 4), {}, {},
                             "auto.json", EngineMarch::Godot);
    QVERIFY(resolved.ok() && resolved->engineLayers && resolved->engineLayers->found);
    const std::string layers =
        "heightmap_min_layers = " + std::to_string(resolved->engineLayers->layers.minLayers) +
        "\nheightmap_max_layers = " + std::to_string(resolved->engineLayers->layers.maxLayers) +
        "\n";
    QVERIFY2(tres.find(layers) != std::string::npos, tres.c_str());

    options.format = ExportFormat::Package;
    options.outDir = (root / "package").string();
    Result<ExportResult> package = exportMaterial(*m, (root / "auto.json").string(), options);
    QVERIFY(package.ok());
    const std::string json = readText(root / "package" / "untitled.json");
    const std::string chosen(info(resolved->material.technique).name);
    QVERIFY2(json.find("\"name\": \"" + chosen + "\"") != std::string::npos, json.c_str());
    // Only the maps the chosen technique reads.
    const bool cone = info(resolved->material.technique).needsConeMap;
    const bool relaxed = info(resolved->material.technique).needsRelaxedConeMap;
    QCOMPARE(std::filesystem::exists(root / "package" / "untitled_cone.png"), cone);
    QCOMPARE(std::filesystem::exists(root / "package" / "untitled_relaxed_cone.png"), relaxed);
}

void AutoTechniqueTest::exportsKeepTheirConeBakes() {
    // Resolving auto with a cone cache folder: the first export bakes the cone maps and keeps
    // them there, the next (a new process: the memory cache cleared) reads them and chooses the
    // same; an export without the folder leaves it alone.
    QTemporaryDir dir;
    const std::filesystem::path root = dir.path().toStdString();
    ImageWriteOptions o;
    o.format = PixelFormat::UInt16;
    QVERIFY(writeImage((root / "stones_height.png").string(),
                       makeProceduralMap(ProceduralMap::Stones, 64, 64, 9).toImage(), o)
                .ok());
    { std::ofstream(root / "auto.json") << kAutoMaterial; }
    Result<Material> m = loadMaterial((root / "auto.json").string());
    QVERIFY(m.ok());
    const std::filesystem::path cache = root / "cones";
    auto cacheFiles = [&] {
        int n = 0;
        if (std::filesystem::exists(cache))
            for (const auto& e : std::filesystem::directory_iterator(cache))
                n += e.path().extension() == ".pxcone" ? 1 : 0;
        return n;
    };
    ExportOptions options;
    options.format = ExportFormat::Package;
    options.outDir = (root / "off").string();
    QVERIFY(exportMaterial(*m, (root / "auto.json").string(), options).ok());
    QCOMPARE(cacheFiles(), 0);

    clearRecommendationCache();
    options.coneCacheDir = cache.string();
    options.outDir = (root / "first").string();
    Result<ExportResult> first = exportMaterial(*m, (root / "auto.json").string(), options);
    QVERIFY2(first.ok(), first.ok() ? "" : first.error().message.c_str());
    QCOMPARE(cacheFiles(), 2); // the cone and the relaxed cone map

    clearRecommendationCache();
    Result<HeightField> height = loadHeightField((root / "stones_height.png").string());
    QVERIFY(height.ok());
    Result<ResolvedAuto> again =
        resolveAutoTechnique(*m, *height, {}, {}, "auto.json", std::nullopt, cache.string());
    QVERIFY(again.ok() && again->recommendation);
    QCOMPARE(again->recommendation->mapsFromDisk, 2);
    QCOMPARE(again->recommendation->mapsBaked, 0);
    QVERIFY2(first->notes.front() == again->note, again->note.c_str());
}

QTEST_GUILESS_MAIN(AutoTechniqueTest)
#include "AutoTechniqueTest.moc"
