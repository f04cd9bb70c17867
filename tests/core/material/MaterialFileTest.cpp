// The material file: round trips keep every field; every invalid value is reported with its JSON
// pointer; newer versions are refused; saving is validated and atomic.

#include "parallax/material/MaterialFile.h"

#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

using namespace px;

class MaterialFileTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void roundTripEveryField();
    void roundTripDefaults();
    void floatsWrittenShort();
    void minimalFileTakesDefaults();
    void techniqueDefaultsFollowTheTechnique();
    void nullMapIsAbsent();
    void problems_data();
    void problems();
    void everyProblemReported();
    void newerVersionRefused();
    void exactMessageFormat();
    void saveRefusesInvalidAndKeepsTarget();
    void saveLeavesNoTemporaryFiles();
    void loadNamesMissingFile();
    void oversizedFileRefused();
    void mapPathsResolveAgainstTheFile();
    void rebaseKeepsTheSameFiles();

private:
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
    QTemporaryDir m_dir;
};

namespace {

Material everyFieldChanged() {
    Material m;
    m.name = "cobbles \"quoted\" ü";
    m.maps = {"a/albedo.png", "h.exr", "n.png", "c.png", "rc.png",
              "ao.png",       "r.png", "m.png", "s.png"};
    m.heightChannel = HeightChannel::Luminance;
    m.heightIsDepth = true;
    m.heightRange = HeightRange{-0.1f, 23.75f};
    m.heightScale = 0.125f;
    m.wrap = WrapMode::Clamp;
    m.tiling = 3.5f;
    m.technique = Technique::Relief;
    m.params = {3, 77, 9, 5, 1234};
    m.normalSource = NormalSource::Map;
    m.normalGreen = NormalGreen::DirectX;
    m.selfShadow = true;
    m.shadowSoftness = 0.25f;
    m.lighting = LightingModel::MetallicRoughness;
    m.roughness = 0.4f;
    m.metallic = 1.0f;
    m.specular = 0.75f;
    m.shininess = 64.0f;
    m.surface = {HeightChannel::Green, HeightChannel::Alpha, HeightChannel::Blue, true};
    m.heightDerivedFrom = "rock_nrm.png";
    m.light = LightDirection{-47.5f, 12.25f};
    return m;
}

void compareMaterials(const Material& a, const Material& b) {
    QCOMPARE(a.name, b.name);
    QCOMPARE(a.maps.albedo, b.maps.albedo);
    QCOMPARE(a.maps.height, b.maps.height);
    QCOMPARE(a.maps.normal, b.maps.normal);
    QCOMPARE(a.maps.cone, b.maps.cone);
    QCOMPARE(a.maps.relaxedCone, b.maps.relaxedCone);
    QCOMPARE(a.maps.ao, b.maps.ao);
    QCOMPARE(a.maps.roughness, b.maps.roughness);
    QCOMPARE(a.maps.metallic, b.maps.metallic);
    QCOMPARE(a.maps.specular, b.maps.specular);
    QCOMPARE(int(a.heightChannel), int(b.heightChannel));
    QCOMPARE(a.heightIsDepth, b.heightIsDepth);
    QVERIFY(a.heightRange == b.heightRange);
    QCOMPARE(a.heightScale, b.heightScale);
    QCOMPARE(int(a.wrap), int(b.wrap));
    QCOMPARE(a.tiling, b.tiling);
    QCOMPARE(int(a.technique), int(b.technique));
    QCOMPARE(a.params.minLayers, b.params.minLayers);
    QCOMPARE(a.params.maxLayers, b.params.maxLayers);
    QCOMPARE(a.params.binarySteps, b.params.binarySteps);
    QCOMPARE(a.params.secantSteps, b.params.secantSteps);
    QCOMPARE(a.params.maxSteps, b.params.maxSteps);
    QCOMPARE(int(a.normalSource), int(b.normalSource));
    QCOMPARE(int(a.normalGreen), int(b.normalGreen));
    QCOMPARE(a.selfShadow, b.selfShadow);
    QCOMPARE(a.shadowSoftness, b.shadowSoftness);
    QCOMPARE(int(a.lighting), int(b.lighting));
    QCOMPARE(a.roughness, b.roughness);
    QCOMPARE(a.metallic, b.metallic);
    QCOMPARE(a.specular, b.specular);
    QCOMPARE(a.shininess, b.shininess);
    QVERIFY(a.surface == b.surface);
    QCOMPARE(a.heightDerivedFrom, b.heightDerivedFrom);
    QVERIFY(a.light == b.light);
}

const char* kHeader = R"("format": "parallax-studio-material", "version": 1)";

std::string withHeader(const std::string& body) {
    return "{" + std::string(kHeader) + (body.empty() ? "" : ", " + body) + "}";
}

} // namespace

void MaterialFileTest::roundTripEveryField() {
    const Material original = everyFieldChanged();
    const std::string file = path("m.json");
    const Status saved = saveMaterial(original, file);
    QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().message.c_str());
    Result<Material> loaded = loadMaterial(file);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    compareMaterials(*loaded, original);
    // Saving what was loaded writes the same bytes: the format is stable.
    QCOMPARE(materialToJson(*loaded), materialToJson(original));
}

void MaterialFileTest::roundTripDefaults() {
    Material original;
    original.maps.height = "h.png";
    Result<Material> loaded = parseMaterial(materialToJson(original), "m.json");
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    compareMaterials(*loaded, original);
}

void MaterialFileTest::floatsWrittenShort() {
    Material m;
    m.maps.height = "h.png";
    const std::string json = materialToJson(m);
    QVERIFY2(json.find("\"scale\": 0.05") != std::string::npos, json.c_str());
    QVERIFY2(json.find("0.0500000") == std::string::npos, json.c_str());
    // The import's packed channels and derived height are written only when set.
    QVERIFY2(json.find("surface") == std::string::npos, json.c_str());
    QVERIFY2(json.find("derivedFrom") == std::string::npos, json.c_str());
    // So are a float height map's range and a specular map.
    QVERIFY2(json.find("range") == std::string::npos, json.c_str());
    QVERIFY2(json.find("\"specular\": \"") == std::string::npos, json.c_str());
    m.heightRange = HeightRange{-1.5f, 0.1f};
    m.maps.specular = "s.png";
    const std::string ranged = materialToJson(m);
    QVERIFY2(ranged.find("\"range\": [\n      -1.5,\n      0.1\n    ]") != std::string::npos,
             ranged.c_str());
    QVERIFY2(ranged.find("\"specular\": \"s.png\"") != std::string::npos, ranged.c_str());
    QVERIFY(json.rfind("{\n  \"format\": \"parallax-studio-material\",\n  \"version\": 1,", 0) ==
            0);
}

void MaterialFileTest::minimalFileTakesDefaults() {
    Result<Material> m = parseMaterial(withHeader(R"("maps": {"height": "h.png"})"), "m.json");
    QVERIFY2(m.ok(), m.ok() ? "" : m.error().message.c_str());
    Material expected;
    expected.maps.height = "h.png";
    compareMaterials(*m, expected);
}

void MaterialFileTest::techniqueDefaultsFollowTheTechnique() {
    Result<Material> m = parseMaterial(
        withHeader(R"("maps": {"height": "h.png"}, "technique": {"name": "relaxed-cone"})"), "m");
    QVERIFY2(m.ok(), m.ok() ? "" : m.error().message.c_str());
    QVERIFY(m->technique == Technique::RelaxedCone);
    QCOMPARE(m->params.maxSteps, info(Technique::RelaxedCone).defaults.maxSteps);
    QCOMPARE(m->params.binarySteps, info(Technique::RelaxedCone).defaults.binarySteps);
}

void MaterialFileTest::nullMapIsAbsent() {
    Result<Material> m =
        parseMaterial(withHeader(R"("maps": {"height": "h.png", "albedo": null})"), "m");
    QVERIFY2(m.ok(), m.ok() ? "" : m.error().message.c_str());
    QVERIFY(m->maps.albedo.empty());
}

void MaterialFileTest::problems_data() {
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("expected"); // one line of the error
    const QString h = R"("maps": {"height": "h.png"}, )";
    auto body = [&](const QString& rest) {
        return QString::fromStdString(withHeader((h + rest).toStdString()));
    };
    QTest::newRow("not json") << "{\"format\": "
                              << "m.json: not valid JSON (parse error at line 1";
    QTest::newRow("empty") << ""
                           << "m.json: not valid JSON (";
    QTest::newRow("array")
        << "[1, 2]"
        << "m.json: expected a JSON object (a Parallax Studio material), got an array";
    QTest::newRow("no format")
        << R"({"version": 1})"
        << R"(m.json: /format: expected "parallax-studio-material", got nothing)";
    QTest::newRow("other format")
        << R"({"format": "gltf", "version": 1})"
        << R"(/format: expected "parallax-studio-material", got "gltf": this is not a Parallax Studio material)";
    QTest::newRow("no version")
        << R"({"format": "parallax-studio-material"})"
        << "m.json: /version: expected the format version (an integer), got nothing";
    QTest::newRow("string version")
        << R"({"format": "parallax-studio-material", "version": "1"})"
        << R"(/version: expected the format version (an integer), got "1")";
    QTest::newRow("version 0") << R"({"format": "parallax-studio-material", "version": 0})"
                               << "/version: expected 1, got 0";
    QTest::newRow("version -3") << R"({"format": "parallax-studio-material", "version": -3})"
                                << "/version: expected 1, got -3";
    QTest::newRow("version 1.5") << R"({"format": "parallax-studio-material", "version": 1.5})"
                                 << "/version: expected the format version (an integer), got 1.5";
    QTest::newRow("unknown key")
        << body(R"("colour": 1)")
        << "m.json: /colour: unknown key (known here: format, version, name,";
    QTest::newRow("unknown nested key")
        << body(R"("technique": {"name": "pom", "maxLayer": 9})")
        << "m.json: /technique/maxLayer: unknown key (known here: name, minLayers,";
    QTest::newRow("slash in key") << body(R"("a/b~c": 1)") << "m.json: /a~1b~0c: unknown key";
    QTest::newRow("surface channel")
        << body(R"("surface": {"roughnessChannel": "purple"})")
        << R"(m.json: /surface/roughnessChannel: expected one of "red", "green", "blue", "alpha", "luminance", got "purple")";
    QTest::newRow("surface gloss")
        << body(R"("surface": {"roughnessIsGloss": 1})")
        << "m.json: /surface/roughnessIsGloss: expected true or false, got 1";
    QTest::newRow("name type") << body(R"("name": 5)") << "m.json: /name: expected a string, got 5";
    QTest::newRow("name empty") << body(R"("name": "")")
                                << "m.json: /name: expected a non-empty name";
    QTest::newRow("maps array") << QString::fromStdString(withHeader(R"("maps": [])"))
                                << "m.json: /maps: expected an object, got an array";
    QTest::newRow("map type") << body(R"("maps": {"height": 3})").replace(h, "")
                              << "m.json: /maps/height: expected a string, got 3";
    QTest::newRow("height needed") << QString::fromStdString(withHeader(""))
                                   << R"(m.json: /maps/height: technique "pom" needs a height map)";
    QTest::newRow("height for normals")
        << QString::fromStdString(withHeader(R"("technique": {"name": "none"})"))
        << R"(m.json: /maps/height: normal source "height-central" needs a height map)";
    QTest::newRow("normal needed")
        << body(R"("normal": {"source": "map"})")
        << R"(m.json: /maps/normal: normal source "map" needs a normal map)";
    QTest::newRow("channel")
        << body(R"("height": {"channel": "purple"})")
        << R"(m.json: /height/channel: expected one of "red", "green", "blue", "alpha", "luminance", got "purple")";
    QTest::newRow("invert") << body(R"("height": {"invert": "yes"})")
                            << R"(m.json: /height/invert: expected true or false, got "yes")";
    QTest::newRow("scale negative") << body(R"("height": {"scale": -0.1})")
                                    << "m.json: /height/scale: expected a number 0..100, got -0.1";
    QTest::newRow("scale huge") << body(R"("height": {"scale": 1e999})")
                                << "m.json: not valid JSON (number overflow parsing '1e999')";
    QTest::newRow("scale string")
        << body(R"("height": {"scale": "big"})")
        << R"(m.json: /height/scale: expected a number 0..100, got "big")";
    QTest::newRow("range type")
        << body(R"("height": {"range": 2})")
        << "m.json: /height/range: expected [lo, hi], the file values for heights 0 and 1, got 2";
    QTest::newRow("range length")
        << body(R"("height": {"range": [0, 1, 2]})")
        << "m.json: /height/range: expected [lo, hi], the file values for heights 0 and 1, got an "
           "array";
    QTest::newRow("range text")
        << body(R"("height": {"range": ["0", 1]})")
        << "m.json: /height/range: expected [lo, hi], the file values for heights 0 and 1, got an "
           "array";
    QTest::newRow("range beyond float")
        << body(R"("height": {"range": [0, 1e300]})")
        << "m.json: /height/range: expected [lo, hi], the file values for heights 0 and 1, got an "
           "array";
    QTest::newRow("range reversed")
        << body(R"("height": {"range": [3, -2]})")
        << "m.json: /height/range: expected lo < hi (the file values for heights 0 and 1), got "
           "[3, -2]";
    QTest::newRow("range empty")
        << body(R"("height": {"range": [0.5, 0.5]})")
        << "m.json: /height/range: expected lo < hi (the file values for heights 0 and 1), got "
           "[0.5, 0.5]";
    QTest::newRow("specular map type")
        << body(R"("maps": {"height": "h.png", "specular": 1})").replace(h, "")
        << "m.json: /maps/specular: expected a string, got 1";
    QTest::newRow("wrap") << body(R"("wrap": "mirror")")
                          << R"(m.json: /wrap: expected one of "repeat", "clamp", got "mirror")";
    QTest::newRow("tiling zero") << body(R"("tiling": 0)")
                                 << "m.json: /tiling: expected a number 0.001..10000, got 0";
    QTest::newRow("technique name")
        << body(R"("technique": {"name": "magic"})")
        << R"(m.json: /technique/name: expected one of "none", "normal", "offset", "steep", "pom", "relief", "secant", "cone", "relaxed-cone", "pyramid", "exact", "auto", got "magic")";
    QTest::newRow("technique type")
        << body(R"("technique": "pom")") << R"(m.json: /technique: expected an object, got "pom")";
    QTest::newRow("maxLayers string")
        << body(R"("technique": {"maxLayers": "x"})")
        << R"(m.json: /technique/maxLayers: expected an integer 1..4096, got "x")";
    QTest::newRow("maxLayers big")
        << body(R"("technique": {"maxLayers": 5000})")
        << "m.json: /technique/maxLayers: expected an integer 1..4096, got 5000";
    QTest::newRow("maxLayers fraction")
        << body(R"("technique": {"maxLayers": 8.5})")
        << "m.json: /technique/maxLayers: expected an integer 1..4096, got 8.5";
    QTest::newRow("minLayers zero")
        << body(R"("technique": {"minLayers": 0})")
        << "m.json: /technique/minLayers: expected an integer 1..4096, got 0";
    QTest::newRow("min over max")
        << body(R"("technique": {"minLayers": 40, "maxLayers": 8})")
        << "m.json: /technique/minLayers: min layers (40) exceed max layers (8)";
    QTest::newRow("binarySteps")
        << body(R"("technique": {"binarySteps": 65})")
        << "m.json: /technique/binarySteps: expected an integer 0..64, got 65";
    QTest::newRow("secantSteps")
        << body(R"("technique": {"secantSteps": -1})")
        << "m.json: /technique/secantSteps: expected an integer 0..64, got -1";
    QTest::newRow("maxSteps")
        << body(R"("technique": {"maxSteps": 1e30})")
        << "m.json: /technique/maxSteps: expected an integer 1..16777216, got 1e+30";
    QTest::newRow("normal source")
        << body(R"("normal": {"source": "bump"})")
        << R"(m.json: /normal/source: expected one of "none", "map", "height-central", "height-sobel", got "bump")";
    QTest::newRow("normal green")
        << body(R"("normal": {"green": "maya"})")
        << R"(m.json: /normal/green: expected one of "opengl", "directx", got "maya")";
    QTest::newRow("shadow enabled") << body(R"("shadow": {"enabled": 1})")
                                    << "m.json: /shadow/enabled: expected true or false, got 1";
    QTest::newRow("softness") << body(R"("shadow": {"softness": 2})")
                              << "m.json: /shadow/softness: expected a number 0..1, got 2";
    QTest::newRow("model")
        << body(R"("lighting": {"model": "toon"})")
        << R"(m.json: /lighting/model: expected one of "blinn-phong", "metallic-roughness", got "toon")";
    QTest::newRow("roughness") << body(R"("lighting": {"roughness": null})")
                               << "m.json: /lighting/roughness: expected a number 0..1, got null";
    QTest::newRow("metallic") << body(R"("lighting": {"metallic": [1]})")
                              << "m.json: /lighting/metallic: expected a number 0..1, got an array";
    QTest::newRow("specular") << body(R"("lighting": {"specular": 1.5})")
                              << "m.json: /lighting/specular: expected a number 0..1, got 1.5";
    QTest::newRow("shininess") << body(R"("lighting": {"shininess": 0})")
                               << "m.json: /lighting/shininess: expected a number 1..10000, got 0";
    QTest::newRow("light elevation")
        << body(R"("light": {"azimuth": 10, "elevation": 95})")
        << "m.json: /light/elevation: expected a number -90..90, got 95";
    QTest::newRow("light azimuth")
        << body(R"("light": {"azimuth": "north"})")
        << R"(m.json: /light/azimuth: expected a number -360..360, got "north")";
}

void MaterialFileTest::problems() {
    QFETCH(QString, json);
    QFETCH(QString, expected);
    Result<Material> m = parseMaterial(json.toStdString(), "m.json");
    QVERIFY(!m.ok());
    const QString message = QString::fromStdString(m.error().message);
    QVERIFY2(message.contains(expected), qPrintable(message));
}

void MaterialFileTest::everyProblemReported() {
    const std::string json = withHeader(
        R"("maps": {"height": "h.png"}, "wrap": "x", "technique": {"maxLayers": "x", "minLayers": 9999}, "shadow": {"softness": -1}, "extra": 1)");
    Result<Material> m = parseMaterial(json, "m.json");
    QVERIFY(!m.ok());
    const QStringList lines = QString::fromStdString(m.error().message).split('\n');
    QCOMPARE(lines.size(), 5);
    for (const QString& line : lines)
        QVERIFY2(line.startsWith("m.json: /"), qPrintable(line));
    // A value already reported is not reported again by the cross-field rules.
    QCOMPARE(lines.filter("/technique/minLayers").size(), 1);
}

void MaterialFileTest::newerVersionRefused() {
    const std::string json =
        R"({"format": "parallax-studio-material", "version": 2, "shiny": {"new": true}})";
    Result<Material> m = parseMaterial(json, "new.json");
    QVERIFY(!m.ok());
    // One sentence about the version; the keys it does not know are not misreported.
    QCOMPARE(QString::fromStdString(m.error().message),
             QString("new.json: /version: version 2 was written by a newer Parallax Studio; this "
                     "one reads version 1 only (update Parallax Studio to open it)"));
    Result<Material> huge = parseMaterial(
        R"({"format": "parallax-studio-material", "version": 18446744073709551615})", "n.json");
    QVERIFY(!huge.ok());
    QVERIFY(huge.error().message.find("newer Parallax Studio") != std::string::npos);
}

void MaterialFileTest::exactMessageFormat() {
    Result<Material> m =
        parseMaterial(withHeader(R"("maps": {"height": "h.png"}, "technique": {"maxLayers": "x"})"),
                      "material.json");
    QVERIFY(!m.ok());
    QCOMPARE(
        QString::fromStdString(m.error().message),
        QString(R"(material.json: /technique/maxLayers: expected an integer 1..4096, got "x")"));
}

void MaterialFileTest::saveRefusesInvalidAndKeepsTarget() {
    const std::string file = path("keep.json");
    QVERIFY(writeTextFile(file, "previous").ok());
    Material m;
    m.maps.height = "h.png";
    m.params.minLayers = 50;
    m.params.maxLayers = 10;
    m.heightScale = -1.0f;
    const Status saved = saveMaterial(m, file);
    QVERIFY(!saved.ok());
    const QString message = QString::fromStdString(saved.error().message);
    QVERIFY2(message.contains(QString::fromStdString(file) +
                              ": /height/scale: expected a number 0..100, got -1"),
             qPrintable(message));
    QVERIFY2(message.contains("/technique/minLayers: min layers (50) exceed max layers (10)"),
             qPrintable(message));
    QCOMPARE(QString::fromStdString(*readTextFile(file)), QString("previous"));
}

void MaterialFileTest::saveLeavesNoTemporaryFiles() {
    QTemporaryDir dir;
    const std::string file = dir.filePath("a.json").toStdString();
    Material m = everyFieldChanged();
    for (int i = 0; i < 3; ++i)
        QVERIFY(saveMaterial(m, file).ok());
    int files = 0;
    for ([[maybe_unused]] const auto& entry :
         std::filesystem::directory_iterator(dir.path().toStdString()))
        ++files;
    QCOMPARE(files, 1);
    const Status bad = saveMaterial(m, path("no/such/folder/a.json"));
    QVERIFY(!bad.ok());
    QVERIFY(bad.error().message.find("no/such/folder/a.json") != std::string::npos);
}

void MaterialFileTest::loadNamesMissingFile() {
    Result<Material> m = loadMaterial(path("missing.json"));
    QVERIFY(!m.ok());
    QCOMPARE(QString::fromStdString(m.error().message),
             QString::fromStdString(path("missing.json") + ": no such file"));
}

void MaterialFileTest::oversizedFileRefused() {
    const std::string file = path("big.json");
    QVERIFY(writeTextFile(file, std::string(2 << 20, ' ')).ok());
    Result<Material> m = loadMaterial(file);
    QVERIFY(!m.ok());
    QVERIFY2(m.error().message.find("too large for a material file") != std::string::npos,
             m.error().message.c_str());
}

void MaterialFileTest::mapPathsResolveAgainstTheFile() {
    QCOMPARE(QString::fromStdString(resolveMapPath("/data/mats/m.json", "tex/h.png")),
             QString("/data/mats/tex/h.png"));
    QCOMPARE(QString::fromStdString(resolveMapPath("/data/mats/m.json", "../h.png")),
             QString("/data/h.png"));
    QCOMPARE(QString::fromStdString(resolveMapPath("/data/mats/m.json", "/abs/h.png")),
             QString("/abs/h.png"));
    QCOMPARE(QString::fromStdString(resolveMapPath("m.json", "h.png")), QString("h.png"));
    QVERIFY(resolveMapPath("/data/m.json", "").empty());
}

void MaterialFileTest::rebaseKeepsTheSameFiles() {
    const std::string from = path("a/b/m.json");
    const std::string to = path("c/m.json");
    MaterialMaps maps;
    maps.height = "tex/h.png";
    maps.albedo = "/abs/albedo.png";
    const MaterialMaps rebased = rebaseMapPaths(maps, from, to);
    QCOMPARE(QString::fromStdString(rebased.height), QString("../a/b/tex/h.png"));
    QCOMPARE(QString::fromStdString(rebased.albedo), QString("/abs/albedo.png"));
    QVERIFY(rebased.normal.empty());
    namespace fs = std::filesystem;
    QCOMPARE(fs::weakly_canonical(resolveMapPath(to, rebased.height)),
             fs::weakly_canonical(resolveMapPath(from, maps.height)));
}

QTEST_GUILESS_MAIN(MaterialFileTest)
#include "MaterialFileTest.moc"
