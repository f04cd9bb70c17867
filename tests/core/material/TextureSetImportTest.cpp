// Importing texture sets the test writes itself: height or depth and OpenGL or DirectX green over
// several seeds are read from the data; every file is used or listed with why; two sets are never
// mixed; a folder with no set is refused with the report; a normal-only set gets a derived height
// on request; failures name their file. (Naming conventions: TextureSetConventionsTest.)

#include "parallax/material/TextureSetImport.h"

#include "ConventionSets.h"
#include "TextureSets.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MapContent.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/ReliefReading.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace px;
using namespace px::test;

namespace {

std::vector<std::string> filesOf(const QTemporaryDir& dir) {
    Result<std::vector<std::string>> files = folderFiles(dir.path().toStdString());
    return files ? *files : std::vector<std::string>{};
}

bool mentions(const std::vector<SkippedFile>& list, const std::string& file,
              const std::string& why) {
    return std::any_of(list.begin(), list.end(), [&](const SkippedFile& s) {
        return s.path.ends_with(file) && s.why.find(why) != std::string::npos;
    });
}

void writePng(const std::string& path, const Image& image) {
    ImageWriteOptions options;
    options.format = PixelFormat::UInt8;
    QVERIFY(writeImage(path, image, options).ok());
}

std::string summaryOf(const ImportedSet& set) {
    std::string text;
    for (const std::string& line : importSummary(set))
        text += line + "\n";
    return text;
}

} // namespace

class TextureSetImportTest : public QObject {
    Q_OBJECT
private slots:
    void everyConventionIsToldFromTheData_data() {
        QTest::addColumn<bool>("depth");
        QTest::addColumn<bool>("directx");
        QTest::addColumn<bool>("albedoSuffix");
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 2u, 3u, 17u, 29u, 40u})
            for (bool depth : {false, true})
                for (bool directx : {false, true}) {
                    const bool suffix = (seed + (depth ? 1 : 0) + (directx ? 2 : 0)) % 2 == 0;
                    QTest::addRow("%s-%s-%s-seed%u", depth ? "depth" : "height",
                                  directx ? "directx" : "opengl", suffix ? "suffix" : "plain", seed)
                        << depth << directx << suffix << seed;
                }
    }
    void everyConventionIsToldFromTheData() {
        QFETCH(bool, depth);
        QFETCH(bool, directx);
        QFETCH(bool, albedoSuffix);
        QFETCH(unsigned, seed);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "Wall" + std::to_string(seed);
        spec.depth = depth;
        spec.green = directx ? NormalGreen::DirectX : NormalGreen::OpenGL;
        spec.albedoSuffix = albedoSuffix;
        spec.seed = seed;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);

        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        QCOMPARE(plan->name, spec.stem);
        QCOMPARE(plan->files.size(), std::size_t(3));
        QVERIFY(plan->ignored.empty());

        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QCOMPARE(set->material.maps.albedo, written.albedoFile);
        QVERIFY(set->relief.fromData);
        QCOMPARE(set->material.heightIsDepth, depth);
        QCOMPARE(set->material.normalGreen, spec.green);
        QCOMPARE(set->material.normalSource, NormalSource::Map);
        QCOMPARE(set->material.name, spec.stem);
        QVERIFY2(set->relief.score > 0.8, set->relief.summary.c_str());
        // The material holds the height written, white = high, at every texel (16-bit file).
        QCOMPARE(set->assets.height.width, written.height.width);
        float worst = 0.0f;
        for (std::size_t i = 0; i < written.height.texels.size(); ++i)
            worst =
                std::max(worst, std::abs(set->assets.height.texels[i] - written.height.texels[i]));
        QVERIFY2(worst <= 1.0f / 65535.0f, QByteArray::number(worst));
        QVERIFY(!set->assets.normal.empty() && !set->assets.albedo.empty());
    }

    void withoutANormalMapTheNameDecidesAndSaysSo() {
        for (bool depth : {false, true}) {
            QTemporaryDir dir;
            TextureSetSpec spec;
            spec.normal = false;
            spec.depth = depth;
            spec.heightSuffix = depth ? "_depth" : "_height";
            writeTextureSet(dir.path().toStdString(), spec);
            const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
            QVERIFY(plan);
            const Result<ImportedSet> set = importTextureSet(*plan);
            QVERIFY(set);
            QVERIFY(!set->relief.fromData);
            QCOMPARE(set->material.heightIsDepth, depth);
            QCOMPARE(set->material.normalSource, NormalSource::HeightCentral);
            QVERIFY(set->relief.summary.find("Guessed from the file name") != std::string::npos);
            QVERIFY(set->relief.summary.find("flip it") != std::string::npos);
        }
    }

    void anotherSetsNormalMapIsNotTrusted() {
        // The normal map of a random height field says nothing about this one: the name decides.
        QTemporaryDir dir, other;
        TextureSetSpec spec;
        spec.normal = false;
        spec.heightSuffix = "_depth";
        writeTextureSet(dir.path().toStdString(), spec);
        TextureSetSpec foreign;
        foreign.seed = 5;
        const WrittenSet written = writeTextureSet(other.path().toStdString(), foreign);
        const std::string normal = dir.filePath("rock_normal.png").toStdString();
        QVERIFY(QFile::copy(QString::fromStdString(written.normalFile),
                            QString::fromStdString(normal)));
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY2(!set->relief.fromData, set->relief.summary.c_str());
        QCOMPARE(set->material.maps.normal, normal); // used as named, with a warning
        QVERIFY(set->material.maps.height.ends_with("rock_depth.png"));
        QVERIFY(set->material.heightIsDepth);
        QVERIFY(set->relief.summary.find("do not follow") != std::string::npos);
    }

    void twoSetsAreNeverMixed() {
        QTemporaryDir dir;
        TextureSetSpec a;
        a.stem = "bricks2";
        a.albedoSuffix = false;
        writeTextureSet(dir.path().toStdString(), a);
        TextureSetSpec b;
        b.stem = "toy_box";
        b.seed = 2;
        writeTextureSet(dir.path().toStdString(), b);
        QVERIFY(writeTextFile(dir.filePath("README.md").toStdString(), "origin"));
        QVERIFY(writeTextFile(dir.filePath("wood.png").toStdString(), "not read"));

        const std::vector<std::string> files = filesOf(dir);
        QCOMPARE(textureSetNames(files), (std::vector<std::string>{"bricks2", "toy_box"}));
        const Result<TextureSetPlan> unchosen = planTextureSet(files, "dir");
        QVERIFY(!unchosen);
        QCOMPARE(QString::fromStdString(unchosen.error().message),
                 QString("dir: holds 2 texture sets (bricks2, toy_box): choose one, they are "
                         "never mixed"));

        const Result<TextureSetPlan> plan = planTextureSet(files, "dir", "TOY_BOX");
        QVERIFY(plan);
        QCOMPARE(plan->name, std::string("toy_box"));
        QCOMPARE(plan->files.size(), std::size_t(3));
        for (const SetFile& f : plan->files)
            QVERIFY2(f.path.find("toy_box") != std::string::npos, f.path.c_str());
        // Every other file is listed with why.
        QCOMPARE(plan->files.size() + plan->ignored.size(), files.size());
        QVERIFY(mentions(plan->ignored, "bricks2_disp.png", "belongs to the set bricks2"));
        QVERIFY(mentions(plan->ignored, "bricks2.png", "belongs to the set bricks2"));
        QVERIFY(mentions(plan->ignored, "README.md", "not an image file"));
        QVERIFY(mentions(plan->ignored, "wood.png", "no map tag"));
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(set);
        for (const std::string& path :
             {set->material.maps.height, set->material.maps.normal, set->material.maps.albedo})
            QVERIFY2(path.find("toy_box") != std::string::npos, path.c_str());

        const Result<TextureSetPlan> none = planTextureSet(files, "dir", "stones");
        QVERIFY(!none);
        QCOMPARE(QString::fromStdString(none.error().message),
                 QString("dir: holds no texture set named 'stones' (it holds bricks2, toy_box)"));
    }

    // A glued tag needs a sibling; the same name in another format (a download's BMP beside its
    // PNG) is not one: stones.png and stones.jpg are the albedo of "stones", not the specular map
    // of a second set "stone", and brickn.png with brickn.tga alone make no set.
    void oneNameInTwoFormatsIsNotItsOwnSibling() {
        QTemporaryDir dir;
        for (const char* name : {"stones_height.png", "stones.png", "stones.jpg"})
            QVERIFY(writeTextFile(dir.filePath(name).toStdString(), "names only"));
        const std::vector<std::string> files = filesOf(dir);
        QCOMPARE(textureSetNames(files), (std::vector<std::string>{"stones"}));
        const Result<TextureSetPlan> plan = planTextureSet(files, "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        QCOMPARE(plan->files.size(), std::size_t(3));
        QVERIFY(plan->ignored.empty());

        QTemporaryDir lone;
        for (const char* name : {"brickn.png", "brickn.tga"})
            QVERIFY(writeTextFile(lone.filePath(name).toStdString(), "names only"));
        QVERIFY(textureSetNames(filesOf(lone)).empty());
        const Result<TextureSetPlan> none = planTextureSet(filesOf(lone), "lone");
        QVERIFY(!none);
        QVERIFY2(none.error().message.find("brickn.png: no map tag") != std::string::npos,
                 none.error().message.c_str());

        QVERIFY(writeTextFile(lone.filePath("brickz.png").toStdString(), "names only"));
        QCOMPARE(textureSetNames(filesOf(lone)), (std::vector<std::string>{"brick"}));
    }

    void duplicatesAreListedAndTheSummaryNamesEveryFile() {
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.albedoSuffix = false;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(QFile::copy(QString::fromStdString(written.heightFile),
                            dir.filePath("rock_height.png")));
        QVERIFY(QFile::copy(QString::fromStdString(written.albedoFile),
                            dir.filePath("rock_color.png")));
        QVERIFY(writeTextFile(dir.filePath("notes.txt").toStdString(), "x"));
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY(plan);
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(set);
        // The tagged albedo wins over the one named after the set; the first height file wins.
        QCOMPARE(set->material.maps.albedo, dir.filePath("rock_color.png").toStdString());
        QCOMPARE(set->material.maps.height, written.heightFile);
        const std::string text = summaryOf(*set);
        for (const char* name : {"rock_disp.png", "rock_normal.png", "rock_color.png", "rock.png",
                                 "rock_height.png", "notes.txt", "Told by the normal map"})
            QVERIFY2(text.find(name) != std::string::npos, (text + " lacks " + name).c_str());
        QVERIFY2(text.find("Not used: rock.png (named after the set, no tag: rock_color.png is the "
                           "albedo)") != std::string::npos,
                 text.c_str());
        QVERIFY2(text.find("Not used: rock_height.png (another file for the same map: "
                           "rock_disp.png is used)") != std::string::npos,
                 text.c_str());
        QVERIFY(text.find("Ignored: notes.txt (not an image file)") != std::string::npos);
    }

    void aBrokenFileFailsTheWholeImportNamingIt() {
        QTemporaryDir dir;
        writeTextureSet(dir.path().toStdString(), {});
        QVERIFY(writeTextFile(dir.filePath("rock_ao.png").toStdString(), "garbage"));
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY(!set);
        QVERIFY2(set.error().message.find("rock_ao.png") != std::string::npos,
                 set.error().message.c_str());
    }

    // A sky-box face named like a normal map (SKY_n beside SKY_s, SKY_e, SKY_w) is not one: its
    // vectors do not point out of the surface (mean z -0.05), so it is reported and not used,
    // and with nothing else to give relief the folder is no material.
    void aNameTheTexelsContradictLoses() {
        QTemporaryDir dir;
        for (const char* face : {"SKY_n", "SKY_s", "SKY_e", "SKY_w"}) {
            Image sky(48, 32, 3);
            for (int y = 0; y < sky.height; ++y)
                for (int x = 0; x < sky.width; ++x) {
                    const float t = static_cast<float>(y) / (sky.height - 1);
                    sky.at(x, y, 0) = 0.70f + 0.1f * t; // a pale sky: n = (0.4..0.6, 0.24, -0.05)
                    sky.at(x, y, 1) = 0.62f;
                    sky.at(x, y, 2) = 0.475f;
                }
            writePng(dir.filePath(QString(face) + ".png").toStdString(), sky);
        }
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(!set);
        QVERIFY2(set.error().message.find("has no height map and no normal map") !=
                         std::string::npos &&
                     set.error().message.find("SKY_n.png (tag _n, but its texels are not a normal "
                                              "map: they do not point out of the surface (mean "
                                              "z -0.05") != std::string::npos,
                 set.error().message.c_str());
        // Beside a real normal map of the set, the contradicted file gives way to it.
        TextureSetSpec spec;
        spec.stem = "SKY";
        spec.albedoSuffix = false;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
        const Result<ImportedSet> real = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(real, real ? "" : real.error().message.c_str());
        QCOMPARE(real->material.maps.normal, written.normalFile);
    }

    // A near-grey albedo named after the set (NAME.png beside NAME_normal.png) whose shading
    // follows the relief's slopes weakly is the albedo, not a height map: weak evidence does not
    // override a name. Its agreement is made between 0.5 and 0.78 here, measured as the importer
    // measures it.
    void weakSlopeEvidenceDoesNotMakeAnAlbedoAHeightMap() {
        QTemporaryDir dir;
        const HeightField relief = makeProceduralMap(ProceduralMap::Noise, 64, 64, 3);
        const HeightField other = makeProceduralMap(ProceduralMap::Noise, 64, 64, 9);
        NormalBakeOptions bake;
        writePng(dir.filePath("wall_normal.png").toStdString(), *bakeNormalMap(relief, bake));
        const Result<Image> stored = readImage(dir.filePath("wall_normal.png").toStdString(), {});
        QVERIFY(stored);
        const Image& normals = *stored; // as the importer reads it
        std::optional<double> agreement;
        for (float w = 0.2f; w <= 0.9f && !agreement; w += 0.02f) {
            Image albedo(64, 64, 3);
            HeightField grey(64, 64);
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 64; ++x) {
                    const float v = 0.3f + 0.4f * (w * relief.at(x, y) + (1 - w) * other.at(x, y));
                    grey.at(x, y) = std::round(v * 255.0f) / 255.0f;
                    for (int c = 0; c < 3; ++c)
                        albedo.at(x, y, c) = grey.at(x, y);
                }
            const Result<ReliefReading> r = readRelief(grey, normals, WrapMode::Repeat, false, "n");
            if (r && r->fromData && r->score >= 0.5 && r->score < 0.78) {
                agreement = r->score;
                writePng(dir.filePath("wall.png").toStdString(), albedo);
            }
        }
        QVERIFY2(agreement.has_value(), "no mix gave a weak agreement");
        qInfo("agreement %.2f", *agreement);
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY2(set->heightMissing, summaryOf(*set).c_str());
        QVERIFY(set->material.maps.albedo.ends_with("wall.png"));
    }

    // Entries named like maps that are no regular files are reported by what they are, never
    // read (a FIFO would hang a reader): a FIFO, a dangling link, a socket, a folder.
    void specialFilesNamedLikeMapsAreReported() {
        QTemporaryDir dir;
        TextureSetSpec spec;
        writeTextureSet(dir.path().toStdString(), spec);
        const std::string base = dir.path().toStdString() + "/";
        QVERIFY(::mkfifo((base + "rock_roughness.png").c_str(), 0600) == 0);
        QVERIFY(::symlink((base + "gone.png").c_str(), (base + "rock_ao.png").c_str()) == 0);
        QVERIFY(QDir().mkpath(dir.filePath("rock_metallic.png")));
        const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
        QVERIFY(sock >= 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        const std::string socketPath = base + "rock_specular.png";
        QVERIFY(socketPath.size() < sizeof address.sun_path);
        std::copy(socketPath.begin(), socketPath.end(), address.sun_path);
        QVERIFY(::bind(sock, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        ::close(sock);
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        QVERIFY(mentions(plan->ignored, "rock_roughness.png",
                         "a FIFO (named pipe), not a regular "
                         "file: not read"));
        QVERIFY(mentions(plan->ignored, "rock_ao.png", "a symbolic link to nothing that exists"));
        QVERIFY(mentions(plan->ignored, "rock_metallic.png", "a folder, not a regular file"));
        QVERIFY(mentions(plan->ignored, "rock_specular.png", "a socket, not a regular file"));
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        const std::string summary = summaryOf(*set);
        QVERIFY2(summary.find("Ignored: rock_roughness.png (a FIFO (named pipe)") !=
                     std::string::npos,
                 summary.c_str());
        QVERIFY(set->material.maps.roughness.empty() && set->material.maps.ao.empty());
    }

    // In a library folder the other sets' files are one line of the report, not one each.
    void otherSetsAreSummarisedOnBigFolders() {
        QTemporaryDir dir;
        TextureSetSpec spec;
        writeTextureSet(dir.path().toStdString(), spec);
        const int sets = 40 + static_cast<int>(QRandomGenerator::global()->bounded(60u));
        for (int i = 0; i < sets; ++i)
            for (const char* tag : {"_albedo", "_normal", "_height"})
                QVERIFY(writeTextFile(
                    dir.filePath(QString("set%1%2.png").arg(i).arg(tag)).toStdString(), "x"));
        const Result<ImportedSet> set =
            importTextureSet(*planTextureSet(filesOf(dir), "dir", "rock"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        const std::vector<std::string> lines = importSummary(*set);
        QVERIFY2(lines.size() < 20, summaryOf(*set).c_str());
        const std::string summary = summaryOf(*set);
        QVERIFY2(summary.find("Ignored: " + std::to_string(3 * sets) + " files of " +
                              std::to_string(sets) +
                              " other texture sets (set0, set1, set10, ...)") != std::string::npos,
                 summary.c_str());
    }

    void aSetNeedsReliefAndAFolderOfNothingIsRefusedWithTheReport() {
        QTemporaryDir dir;
        QVERIFY(writeTextFile(dir.filePath("rock_albedo.png").toStdString(), "x"));
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY(plan);
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(!set);
        QVERIFY2(set.error().message.find("The texture set rock has no height map and no normal "
                                          "map") == 0,
                 set.error().message.c_str());
        const Result<TextureSetPlan> none = planTextureSet(
            {"/x/notes.txt", "/x/IMG_0001.jpg", "/x/rock_emission.png", "/x/stone_nm.dds"}, "x");
        QVERIFY(!none);
        QCOMPARE(QString::fromStdString(none.error().message),
                 QString("x: no texture set recognised (no file named as a height, normal or "
                         "colour map of a set)\n"
                         "  IMG_0001.jpg: no map tag (_albedo, _disp, _normal, ...), and not "
                         "named after a set here\n"
                         "  notes.txt: not an image file\n"
                         "  rock_emission.png: tag _emission (emission), of no texture set here\n"
                         "  stone_nm.dds: an image format not read here (.dds): convert it to PNG, "
                         "TGA, TIFF or EXR"));
    }

    void mapsOneFolderDownAsDownloadsKeepThem() {
        // Poly Haven's download: the .blend at the top, the maps in textures/.
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("textures"));
        QVERIFY(QDir(dir.path()).mkdir(".cache"));
        QVERIFY(writeTextFile(dir.filePath("brick_wall_001_1k.blend").toStdString(), "blend"));
        QVERIFY(
            writeTextFile(dir.filePath(".cache/brick_wall_001_disp_1k.png").toStdString(), "x"));
        writeConventionSet(dir.filePath("textures").toStdString(),
                           {{"brick_wall_001_diff_1k.jpg", Texels::Albedo},
                            {"brick_wall_001_disp_1k.png", Texels::Height},
                            {"brick_wall_001_nor_gl_1k.png", Texels::Normal}},
                           4, NormalGreen::OpenGL);
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        QCOMPARE(plan->name, std::string("brick_wall_001"));
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(set);
        QVERIFY(set->material.maps.height.ends_with("/textures/brick_wall_001_disp_1k.png"));
        QVERIFY(summaryOf(*set).find("Ignored: brick_wall_001_1k.blend (not an image file)") !=
                std::string::npos);
    }

    void aNormalOnlySetGetsADerivedHeightOnRequest() {
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "tiles";
        spec.seed = 3;
        spec.size = 96;
        spec.green = NormalGreen::DirectX;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(QFile::remove(QString::fromStdString(written.heightFile)));
        Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY(set->heightMissing);
        QVERIFY(set->material.maps.height.empty() && set->assets.height.empty());
        QCOMPARE(set->material.normalGreen, NormalGreen::DirectX); // from the curl alone
        QVERIFY2(summaryOf(*set).find("No height map") != std::string::npos,
                 summaryOf(*set).c_str());

        QVERIFY(deriveHeight(*set));
        QVERIFY(!set->heightMissing);
        QCOMPARE(set->material.heightDerivedFrom, std::string("tiles_normal.png"));
        QVERIFY(set->material.maps.height.empty()); // no file until saved
        QCOMPARE(set->assets.height.width, spec.size);
        // Close to the height the normal map was baked from (scale 0.05): 5% RMS of its range.
        double meanA = 0.0, meanB = 0.0, lo = 1.0, hi = 0.0;
        const std::size_t n = written.height.texels.size();
        for (std::size_t i = 0; i < n; ++i) {
            meanA += set->assets.height.texels[i] * set->material.heightScale;
            meanB += written.height.texels[i] * 0.05;
            lo = std::min(lo, double(written.height.texels[i]));
            hi = std::max(hi, double(written.height.texels[i]));
        }
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double e =
                (set->assets.height.texels[i] * set->material.heightScale - meanA / n) -
                (written.height.texels[i] * 0.05 - meanB / n);
            sum += e * e;
        }
        QVERIFY2(std::sqrt(sum / n) < 0.05 * (hi - lo) * 0.05, qPrintable(QString::number(sum)));
        const std::string text = summaryOf(*set);
        QVERIFY2(text.find("derived from the normal map tiles_normal.png") != std::string::npos,
                 text.c_str());
        QVERIFY(!deriveHeight(*set)); // once
    }

    // Float height maps in their makers' units (signed, centimetres, tiny, far from zero; height
    // or depth; either green): read as stored by their own range, which the material records and
    // which reads them back the same through the material file; the relief is told as for a PNG.
    void aFloatMapInItsOwnUnitsIsReadByItsRange_data() {
        QTest::addColumn<float>("offset");
        QTest::addColumn<float>("scale");
        QTest::addColumn<bool>("depth");
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {4u, 8u, 12u}) {
            const float f = 0.5f + 0.25f * static_cast<float>(seed % 5);
            QTest::addRow("signed-seed%u", seed) << -0.7f * f << 1.9f * f << false << seed;
            QTest::addRow("centimetres-depth-seed%u", seed) << 0.0f << 350.0f * f << true << seed;
            QTest::addRow("tiny-signed-seed%u", seed) << -3e-5f * f << 6e-5f * f << false << seed;
            QTest::addRow("far-from-zero-seed%u", seed) << 1000.0f * f << 0.5f << true << seed;
        }
    }
    void aFloatMapInItsOwnUnitsIsReadByItsRange() {
        QFETCH(float, offset);
        QFETCH(float, scale);
        QFETCH(bool, depth);
        QFETCH(unsigned, seed);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "bake";
        spec.seed = seed;
        spec.depth = depth;
        spec.green = seed % 8 ? NormalGreen::OpenGL : NormalGreen::DirectX;
        spec.fileOffset = offset;
        spec.fileScale = scale;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        const Material& m = set->material;
        QVERIFY(m.heightRange);
        QCOMPARE(m.heightRange->lo, written.file.minHeight());
        QCOMPARE(m.heightRange->hi, written.file.maxHeight());
        QCOMPARE(m.heightIsDepth, depth);
        QCOMPARE(m.normalGreen, spec.green);
        QVERIFY(set->relief.fromData);
        const std::string text = summaryOf(*set);
        QVERIFY2(text.find("bake_disp.exr holds heights from ") != std::string::npos, text.c_str());
        // White = high over [0, 1]: the written relief spread over its range, to the float file's
        // precision at its magnitude.
        const float lo = written.height.minHeight(), hi = written.height.maxHeight();
        const float magnitude = std::max(std::abs(m.heightRange->lo), std::abs(m.heightRange->hi));
        const double tolerance = 2.0 * (std::nextafter(magnitude, INFINITY) - magnitude) /
                                     (double(m.heightRange->hi) - m.heightRange->lo) +
                                 1e-6;
        double worst = 0.0;
        for (std::size_t i = 0; i < written.height.texels.size(); ++i)
            worst = std::max(worst, std::abs(double(set->assets.height.texels[i]) -
                                             (written.height.texels[i] - lo) / double(hi - lo)));
        QVERIFY2(worst <= tolerance, qPrintable(QString("%1 > %2").arg(worst).arg(tolerance)));

        // Through the material file: the same heights, texel for texel.
        const std::string file = dir.filePath("bake.json").toStdString();
        QVERIFY(saveMaterial(m, file));
        const Result<Material> loaded = loadMaterial(file);
        QVERIFY(loaded && loaded->heightRange == m.heightRange);
        MapSet height;
        height.height = true;
        const Result<MaterialAssets> assets = loadMaterialAssets(*loaded, file, height);
        QVERIFY2(assets, assets ? "" : assets.error().message.c_str());
        for (std::size_t i = 0; i < written.height.texels.size(); ++i)
            QCOMPARE(assets->height.texels[i], set->assets.height.texels[i]);
    }

    // A float map of one value outside [0, 1] has no range; one with NaN or infinity is refused:
    // each names the file, and nothing is clamped.
    void aFloatMapWithoutARangeOrWithNaNIsRefusedNamingIt() {
        for (const float bad : {7.25f, std::nanf(""), -INFINITY}) {
            QTemporaryDir dir;
            TextureSetSpec spec;
            spec.fileScale = 1.0f;
            const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
            Image image = written.file.toImage();
            if (std::isnan(bad) || std::isinf(bad)) {
                image.at(5, 9, 0) = bad;
            } else {
                for (float& v : image.pixels)
                    v = bad;
            }
            ImageWriteOptions write;
            write.format = PixelFormat::Float;
            QVERIFY(writeImage(written.heightFile, image, write));
            const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
            QVERIFY(!set);
            const std::string& message = set.error().message;
            QVERIFY2(message.starts_with(written.heightFile + ": "), message.c_str());
            QVERIFY2(message.find(std::isfinite(bad) ? "every height texel holds 7.25"
                                                     : "NaN or infinite") != std::string::npos,
                     message.c_str());
        }
    }
};

QTEST_GUILESS_MAIN(TextureSetImportTest)
#include "TextureSetImportTest.moc"
