// Sky boxes of six cube faces: the common names find a set's six files, the faces land where an
// OpenGL samplerCube puts them in the environment's frame, and a set missing a face or mixing
// sizes is one clear error naming the file.

#include "parallax/light/CubeMapSky.h"

#include "parallax/image/ImageFile.h"
#include "parallax/light/Environment.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <random>

using namespace px;

namespace {

// A distinct colour per face, in CubeFace order.
glm::vec3 faceColour(int face) {
    return {1.0f + face, 10.0f - face, 0.5f * face};
}

// Faces of one colour each, `side` texels; face `gradient` (if any) holds s across in red and t
// down in green, to show its orientation.
std::array<Image, 6> testFaces(int side, int gradient = -1) {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = Image(side, side, 3);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                for (int c = 0; c < 3; ++c)
                    faces[f].at(x, y, c) = faceColour(f)[c];
        if (f == gradient)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    faces[f].at(x, y, 0) = (x + 0.5f) / side;
                    faces[f].at(x, y, 1) = (y + 0.5f) / side;
                }
    }
    return faces;
}

// The face a direction's largest component points to (the major axis), in CubeFace order.
int majorFace(glm::vec3 d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0 ? 2 : 3;
    return d.z >= 0 ? 4 : 5;
}

} // namespace

class CubeMapSkyTest : public QObject {
    Q_OBJECT

private slots:
    void everyNamingFindsItsSixFaces_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("face");
        QTest::addColumn<QStringList>("six");
        QTest::addRow("px") << "sky/cloudy_px.hdr" << 0
                            << QStringList{"cloudy_px.hdr", "cloudy_nx.hdr", "cloudy_py.hdr",
                                           "cloudy_ny.hdr", "cloudy_pz.hdr", "cloudy_nz.hdr"};
        QTest::addRow("posx alone")
            << "negy.jpg" << 3
            << QStringList{"posx.jpg", "negx.jpg", "posy.jpg", "negy.jpg", "posz.jpg", "negz.jpg"};
        QTest::addRow("Right") << "Right.png" << 0
                               << QStringList{"Right.png",  "Left.png",  "Top.png",
                                              "Bottom.png", "Front.png", "Back.png"};
        QTest::addRow("_ft") << "mountain_ft.tga" << 4
                             << QStringList{"mountain_rt.tga", "mountain_lf.tga",
                                            "mountain_up.tga", "mountain_dn.tga",
                                            "mountain_ft.tga", "mountain_bk.tga"};
        QTest::addRow("UPPER") << "SKY-BK.EXR" << 5
                               << QStringList{"SKY-RT.EXR", "SKY-LF.EXR", "SKY-UP.EXR",
                                              "SKY-DN.EXR", "SKY-FT.EXR", "SKY-BK.EXR"};
    }
    void everyNamingFindsItsSixFaces() {
        QFETCH(QString, file);
        QFETCH(int, face);
        QFETCH(QStringList, six);
        const std::optional<CubeFaceFiles> files = cubeFaceFiles(file.toStdString());
        QVERIFY(files);
        QCOMPARE(static_cast<int>(files->face), face);
        const std::filesystem::path folder =
            std::filesystem::path(file.toStdString()).parent_path();
        for (int f = 0; f < 6; ++f)
            QCOMPARE(QString::fromStdString(files->paths[f]),
                     QString::fromStdString((folder / six[f].toStdString()).string()));
    }

    void otherNamesAreNoFace() {
        for (const char* name : {"sky.hdr", "backup.exr", "lookup.hdr", "studio_4k.hdr",
                                 "setup.png", "relaxed_cone.png"})
            QVERIFY2(!cubeFaceFiles(name), name);
    }

    // Every texel of the map lies on the face its direction's major axis names (one colour a
    // face), and two faces' gradients run as a samplerCube reads them: +Z's s with +x, t down -y;
    // +Y's s with +x, t with +z.
    void facesLandWhereOpenGlPutsThem() {
        const int width = 256;
        const Image plain = equirectFromCube(testFaces(16), width);
        QCOMPARE(plain.width, width);
        QCOMPARE(plain.height, width / 2);
        int checked = 0;
        for (int y = 0; y < plain.height; ++y)
            for (int x = 0; x < plain.width; ++x) {
                const glm::vec3 d =
                    equirectDirection({(x + 0.5f) / plain.width, (y + 0.5f) / plain.height});
                const glm::vec3 a = glm::abs(d);
                const float top = std::max({a.x, a.y, a.z});
                const float second = a.x + a.y + a.z - top - std::min({a.x, a.y, a.z});
                if (top - second < 1e-4f)
                    continue; // on an edge of the cube: either face
                const glm::vec3 c(plain.at(x, y, 0), plain.at(x, y, 1), plain.at(x, y, 2));
                const int face = majorFace(d);
                QVERIFY2(glm::length(c - faceColour(face)) < 1e-5f,
                         qPrintable(QString("texel %1, %2 (face %3)").arg(x).arg(y).arg(face)));
                ++checked;
            }
        QVERIFY(checked > plain.width * plain.height * 9 / 10);

        const int side = 64;
        const Image front = equirectFromCube(testFaces(side, 4), 512);
        const Image top = equirectFromCube(testFaces(side, 2), 512);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> across(-0.8f, 0.8f);
        for (int i = 0; i < 200; ++i) {
            const float p = across(rng), q = across(rng);
            // +Z: d = (p, q, 1): s = (p + 1) / 2, t = (-q + 1) / 2.
            const glm::vec3 f = sampleEquirect(front, {p, q, 1.0f});
            QVERIFY2(std::abs(f.x - 0.5f * (p + 1.0f)) < 0.03f &&
                         std::abs(f.y - 0.5f * (1.0f - q)) < 0.03f,
                     qPrintable(QString("+Z at %1, %2: %3, %4").arg(p).arg(q).arg(f.x).arg(f.y)));
            // +Y: d = (p, 1, q): s = (p + 1) / 2, t = (q + 1) / 2.
            const glm::vec3 t = sampleEquirect(top, {p, 1.0f, q});
            QVERIFY2(std::abs(t.x - 0.5f * (p + 1.0f)) < 0.03f &&
                         std::abs(t.y - 0.5f * (q + 1.0f)) < 0.03f,
                     qPrintable(QString("+Y at %1, %2: %3, %4").arg(p).arg(q).arg(t.x).arg(t.y)));
        }
    }

    // loadEnvironment given any one face reads the six; a face missing or of another size is an
    // error naming that file.
    void loadingOneFaceReadsTheSky() {
        QTemporaryDir dir;
        const std::array<Image, 6> faces = testFaces(32);
        const char* names[] = {"sky_px.exr", "sky_nx.exr", "sky_py.exr",
                               "sky_ny.exr", "sky_pz.exr", "sky_nz.exr"};
        ImageWriteOptions exr;
        exr.format = PixelFormat::Float;
        for (int f = 0; f < 6; ++f)
            QVERIFY(writeImage(dir.filePath(names[f]).toStdString(), faces[f], exr).ok());
        Result<Image> sky = loadEnvironment(dir.filePath("sky_ny.exr").toStdString());
        QVERIFY2(sky, sky ? "" : sky.error().message.c_str());
        QCOMPARE(sky->width, 128); // four faces round the horizon
        QVERIFY(glm::length(sampleEquirect(*sky, {0, -1, 0}) - faceColour(3)) < 1e-5f);
        QVERIFY(glm::length(sampleEquirect(*sky, {-1, 0.1f, 0.2f}) - faceColour(1)) < 1e-5f);

        QVERIFY(writeImage(dir.filePath("sky_pz.exr").toStdString(), Image(16, 16, 3), exr).ok());
        Result<Image> mixed = loadEnvironment(dir.filePath("sky_px.exr").toStdString());
        QVERIFY(!mixed);
        QVERIFY2(QString::fromStdString(mixed.error().message)
                     .endsWith("sky_pz.exr: is 16 x 16; the other faces are 32 x 32"),
                 mixed.error().message.c_str());
        QVERIFY(QFile::remove(dir.filePath("sky_pz.exr")));
        Result<Image> missing = loadEnvironment(dir.filePath("sky_px.exr").toStdString());
        QVERIFY(!missing);
        QVERIFY2(QString::fromStdString(missing.error().message)
                     .contains("sky_pz.exr: is missing: a cube map needs all six faces"),
                 missing.error().message.c_str());
        // A square file with another name is still refused as an equirectangular one.
        QVERIFY(writeImage(dir.filePath("square.exr").toStdString(), Image(8, 8, 3), exr).ok());
        Result<Image> square = loadEnvironment(dir.filePath("square.exr").toStdString());
        QVERIFY(!square);
        QVERIFY(QString::fromStdString(square.error().message).contains("twice as wide as high"));
    }
};

QTEST_APPLESS_MAIN(CubeMapSkyTest)
#include "CubeMapSkyTest.moc"
