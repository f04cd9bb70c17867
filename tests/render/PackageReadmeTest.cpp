// The exported package works on its own: a program that knows only the package's README.txt and
// its files (the shader text, the maps) binds every texture as the README says, sets every uniform
// to the README's value, draws, and gets the image `render` draws of the same package.

#include "RenderTestSupport.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/export/Exporter.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/render/Camera.h"
#include "parallax/render/GpuMaterial.h"
#include "parallax/render/Mesh.h"
#include "parallax/render/RenderTarget.h"
#include "parallax/render/Renderer.h"
#include "parallax/sample/ProceduralMaps.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

using namespace px;

namespace {

constexpr glm::ivec2 kSize{96, 64};

struct ReadmeUniform {
    QString type, name, value;
};
struct ReadmeBinding {
    int unit = -1;
    QString name, file, format;
};

GLuint compile(GLenum stage, const std::string& text, QString& log) {
    const GLuint shader = glCreateShader(stage);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char buffer[4096];
        glGetShaderInfoLog(shader, sizeof buffer, nullptr, buffer);
        log += buffer;
    }
    return shader;
}

// Uploads `file` the way the README's format text asks, bound on the active texture unit.
GLuint upload(const std::string& file, const QString& format, GLint wrap) {
    const Result<Image> image = readImage(file);
    if (!image)
        return 0;
    const Image& im = *image;
    std::vector<float> rgba(static_cast<std::size_t>(im.width) * im.height * 4, 1.0f);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            for (int c = 0; c < std::min(im.channels, 4); ++c)
                rgba[(static_cast<std::size_t>(y) * im.width + x) * 4 + c] = im.at(x, y, c);
    GLenum internal = GL_RGBA8;
    if (format.startsWith("GL_R16 "))
        internal = GL_R16;
    else if (format.startsWith("GL_R32F"))
        internal = GL_R32F;
    else if (format.startsWith("GL_RG32F"))
        internal = GL_RG32F;
    else if (format.startsWith("GL_RGBA16 ") || format.startsWith("GL_RGBA16,"))
        internal = GL_RGBA16;
    else if (format.contains("GL_SRGB8_ALPHA8"))
        internal = GL_SRGB8_ALPHA8;
    const bool mipmapped = format.contains("mipmapped");
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // The file's own integers, as a program loading it hands them to GL: GL converts float data
    // into an sRGB format by encoding it (Mesa does), which would encode the albedo twice.
    if (internal == GL_RGBA8 || internal == GL_SRGB8_ALPHA8) {
        std::vector<unsigned char> bytes(rgba.size());
        for (std::size_t i = 0; i < rgba.size(); ++i)
            bytes[i] = static_cast<unsigned char>(std::lround(rgba[i] * 255.0f));
        glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), im.width, im.height, 0,
                     GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), im.width, im.height, 0,
                     GL_RGBA, GL_FLOAT, rgba.data());
    }
    if (mipmapped)
        glGenerateMipmap(GL_TEXTURE_2D);
    else
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    // The filter the README names; magnification linear where the minification filter is.
    GLint minFilter = GL_NEAREST;
    if (format.contains("GL_LINEAR_MIPMAP_LINEAR"))
        minFilter = GL_LINEAR_MIPMAP_LINEAR;
    else if (format.contains("GL_NEAREST_MIPMAP_NEAREST"))
        minFilter = GL_NEAREST_MIPMAP_NEAREST;
    else if (format.contains("GL_LINEAR"))
        minFilter = GL_LINEAR;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                    minFilter == GL_NEAREST || minFilter == GL_NEAREST_MIPMAP_NEAREST ? GL_NEAREST
                                                                                      : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    return texture;
}

std::vector<float> numbersIn(const QString& text) {
    std::vector<float> values;
    static const QRegularExpression number("-?[0-9]+(\\.[0-9]+)?(e-?[0-9]+)?");
    for (auto it = number.globalMatch(text); it.hasNext();)
        values.push_back(it.next().captured(0).toFloat());
    return values;
}

} // namespace

class PackageReadmeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(test::glContext()); }
    void drawsFromTheReadmeAlone_data();
    void drawsFromTheReadmeAlone();
};

// Each row draws a package; `change` departs from the README in one point, and the draw must
// then differ from render's: the comparison can fail, and each value the README names matters.
void PackageReadmeTest::drawsFromTheReadmeAlone_data() {
    QTest::addColumn<int>("technique");
    QTest::addColumn<bool>("shadow");
    QTest::addColumn<bool>("metallicRoughness");
    QTest::addColumn<bool>("directxNormalMap");
    // "", "leave NAME" (at GL's 0), "negate NAME", "linear albedo", "nearest heights"
    QTest::addColumn<QString>("change");
    const int pom = static_cast<int>(Technique::Pom);
    QTest::newRow("pom") << pom << false << false << false << "";
    QTest::newRow("relief+shadow")
        << static_cast<int>(Technique::Relief) << true << false << false << "";
    QTest::newRow("relaxed-cone metallic-roughness")
        << static_cast<int>(Technique::RelaxedCone) << false << true << false << "";
    QTest::newRow("pom directx normal map") << pom << false << false << true << "";
    QTest::newRow("without pxHeightMax") << pom << false << false << false << "leave pxHeightMax";
    QTest::newRow("without pxTiling") << pom << false << false << false << "leave pxTiling";
    QTest::newRow("without pxBaseColor") << pom << false << false << false << "leave pxBaseColor";
    QTest::newRow("light towards the surface")
        << pom << false << false << false << "negate pxLightDir";
    QTest::newRow("green sign flipped")
        << pom << false << false << true << "negate pxNormalGreenSign";
    QTest::newRow("albedo not decoded from sRGB")
        << pom << false << false << false << "linear albedo";
    QTest::newRow("heights not filtered") << pom << false << false << false << "nearest heights";
}

void PackageReadmeTest::drawsFromTheReadmeAlone() {
    QFETCH(int, technique);
    QFETCH(bool, shadow);
    QFETCH(bool, metallicRoughness);
    QFETCH(bool, directxNormalMap);
    QFETCH(QString, change);
    QTemporaryDir dir;
    const std::string root = dir.path().toStdString();
    // The sample material as files, exported as a package.
    const MaterialAssets assets = test::bricksAssets(64);
    ImageWriteOptions sixteen;
    sixteen.format = PixelFormat::UInt16;
    QVERIFY(writeImage(root + "/b_height.png", assets.height.toImage(), sixteen).ok());
    ImageWriteOptions srgb;
    srgb.srgb = true;
    QVERIFY(writeImage(root + "/b_albedo.png", assets.albedo, srgb).ok());
    Material m = test::sampleMaterial(static_cast<Technique>(technique));
    m.maps.height = "b_height.png";
    m.maps.albedo = "b_albedo.png";
    m.selfShadow = shadow;
    m.tiling = 2.0f;
    if (metallicRoughness) {
        m.lighting = LightingModel::MetallicRoughness;
        QVERIFY(writeImage(root + "/b_roughness.png",
                           makeProceduralMap(ProceduralMap::Noise, 64, 64).toImage(), {})
                    .ok());
        m.maps.roughness = "b_roughness.png";
        m.metallic = 0.3f;
    }
    ExportOptions options;
    if (directxNormalMap) { // the package's normal map in DirectX's convention: green sign -1
        NormalBakeOptions bake;
        bake.heightScale = m.heightScale;
        Result<Image> normals = bakeNormalMap(assets.height, bake);
        QVERIFY(normals.ok());
        QVERIFY(writeImage(root + "/b_normal.png", *normals, {}).ok());
        m.maps.normal = "b_normal.png";
        m.normalSource = NormalSource::Map;
        options.packageGreen = NormalGreen::DirectX;
    }
    options.outDir = root + "/pkg";
    Result<ExportResult> exported = exportMaterial(m, root + "/b.json", options);
    QVERIFY2(exported.ok(), exported.ok() ? "" : exported.error().message.c_str());

    OrbitCamera camera;
    camera.azimuthDeg = 25.0f;
    camera.elevationDeg = 35.0f;
    camera.distance = 2.4f;
    DirectionalLight light;

    // What `render --material pkg/bricks.json` draws.
    Result<Material> packaged = loadMaterial(root + "/pkg/bricks.json");
    QVERIFY(packaged.ok());
    Result<MaterialAssets> loaded =
        loadMaterialAssets(*packaged, root + "/pkg/bricks.json", mapsUsed(*packaged));
    QVERIFY(loaded.ok());
    Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(*loaded, packaged->wrap);
    QVERIFY(gpu.ok());
    Result<std::unique_ptr<Renderer>> renderer = Renderer::create();
    QVERIFY(renderer.ok());
    Result<Image> reference =
        (*renderer)->renderImage(**gpu, *packaged, camera, light, DrawOptions{}, kSize);
    QVERIFY(reference.ok());

    // From the README alone.
    const QString readme = QString::fromStdString(*readTextFile(root + "/pkg/README.txt"));
    std::vector<ReadmeUniform> uniforms;
    std::vector<ReadmeBinding> bindings;
    static const QRegularExpression uniformLine(
        "^  (\\S+) (px\\w+) = (.+)  \\((must set|default safe): ",
        QRegularExpression::MultilineOption);
    static const QRegularExpression bindingLine(
        "^  sampler2D (px\\w+)  binding ([0-9]+): (\\S+) as (.+)$",
        QRegularExpression::MultilineOption);
    for (auto it = uniformLine.globalMatch(readme); it.hasNext();) {
        const auto match = it.next();
        uniforms.push_back({match.captured(1), match.captured(2), match.captured(3)});
    }
    for (auto it = bindingLine.globalMatch(readme); it.hasNext();) {
        const auto match = it.next();
        bindings.push_back(
            {match.captured(2).toInt(), match.captured(1), match.captured(3), match.captured(4)});
    }
    QVERIFY2(!uniforms.empty() && !bindings.empty(), qPrintable(readme));
    QVERIFY2(readme.contains("pxFragColor is already sRGB-encoded"), qPrintable(readme));
    const GLint wrap =
        readme.contains("Every texture: wrap GL_REPEAT") ? GL_REPEAT : GL_CLAMP_TO_EDGE;

    QString log;
    const GLuint vs = compile(GL_VERTEX_SHADER, *readTextFile(root + "/pkg/bricks.vert"), log);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, *readTextFile(root + "/pkg/bricks.frag"), log);
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    QVERIFY2(linked && log.isEmpty(), qPrintable(log));
    glUseProgram(program);

    const float aspect = static_cast<float>(kSize.x) / static_cast<float>(kSize.y);
    const glm::mat4 model(1.0f);
    bool changed = change.isEmpty();
    for (const ReadmeUniform& u : uniforms) {
        const GLint at = glGetUniformLocation(program, u.name.toLatin1().constData());
        std::vector<float> n = numbersIn(u.value);
        const float sign = change == "negate " + u.name ? -1.0f : 1.0f;
        changed = changed || sign < 0.0f || change == "leave " + u.name;
        for (float& value : n)
            value *= sign;
        if (change == "leave " + u.name)
            continue;
        if (u.value == "your mesh's")
            glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(model));
        else if (u.value == "from pxModel")
            glUniformMatrix3fv(at, 1, GL_FALSE,
                               glm::value_ptr(glm::inverseTranspose(glm::mat3(model))));
        else if (u.name == "pxViewProjection")
            glUniformMatrix4fv(at, 1, GL_FALSE,
                               glm::value_ptr(camera.projection(aspect) * camera.view()));
        else if (u.name == "pxCameraPos")
            glUniform3fv(at, 1, glm::value_ptr(camera.position()));
        else if (u.name == "pxLightDir")
            glUniform3fv(at, 1, glm::value_ptr(sign * light.direction()));
        else if (u.type == "int" && n.size() == 1)
            glUniform1i(at, static_cast<int>(n[0]));
        else if (u.type == "float" && n.size() == 1)
            glUniform1f(at, n[0]);
        else if (u.type == "vec2" && n.size() == 2)
            glUniform2f(at, n[0], n[1]);
        else if (u.type == "vec3" && n.size() == 3)
            glUniform3f(at, n[0], n[1], n[2]);
        else
            QFAIL(qPrintable("the README gives no usable value for " + u.name + ": " + u.value));
    }
    std::vector<GLuint> textures;
    for (const ReadmeBinding& b : bindings) {
        // Its own unit before the upload binds it: uploading on the unit left active by the
        // previous binding replaced that texture (the first attempt's 14.6-step difference).
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(b.unit));
        QString format = b.format;
        if (change == "linear albedo" && b.name == "pxAlbedoMap")
            format = "GL_RGBA8, mipmapped, GL_LINEAR_MIPMAP_LINEAR";
        else if (change == "nearest heights" && b.name == "pxHeightMap")
            format = "GL_R16 , mipmapped, GL_NEAREST_MIPMAP_NEAREST";
        changed = changed || format != b.format;
        const GLuint texture = upload(root + "/pkg/" + b.file.toStdString(), format, wrap);
        QVERIFY2(texture != 0, qPrintable(b.file));
        textures.push_back(texture);
        glUniform1i(glGetUniformLocation(program, b.name.toLatin1().constData()), b.unit);
    }
    glActiveTexture(GL_TEXTURE0);
    QVERIFY2(changed, qPrintable("the README names nothing that " + change + " could change"));

    // The mesh: vertex attributes at the README's locations.
    QVERIFY(readme.contains("location 0 position, 1 normal, 2 uv, 3 tangent (dP/du), "
                            "4 bitangent (dP/dv)"));
    const MeshData plane = makeMesh(MeshKind::Plane);
    GLuint vao = 0, buffers[2] = {0, 0};
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(plane.vertices.size() * sizeof(MeshVertex)),
                 plane.vertices.data(), GL_STATIC_DRAW);
    const std::size_t offsets[] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal),
                                   offsetof(MeshVertex, uv), offsetof(MeshVertex, tangent),
                                   offsetof(MeshVertex, bitangent)};
    const int sizes[] = {3, 3, 2, 3, 3};
    for (GLuint location = 0; location < 5; ++location) {
        glEnableVertexAttribArray(location);
        // GL takes a buffer offset as a pointer.
        const auto* offset =
            reinterpret_cast<const void*>(offsets[location]); // NOLINT(performance-no-int-to-ptr)
        glVertexAttribPointer(location, sizes[location], GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                              offset);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(plane.indices.size() * sizeof(unsigned)),
                 plane.indices.data(), GL_STATIC_DRAW);

    // A plain RGBA8 target, GL_FRAMEBUFFER_SRGB off, as the README says.
    Result<RenderTarget> target = RenderTarget::create(kSize, TargetFormat::Rgba8);
    QVERIFY(target.ok());
    target->bind();
    glDisable(GL_FRAMEBUFFER_SRGB);
    glViewport(0, 0, kSize.x, kSize.y);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(plane.indices.size()), GL_UNSIGNED_INT,
                   nullptr);
    const Image drawn = target->read();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(2, buffers);
    glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);

    // The one intended difference: the albedo sampled from the file's 8-bit sRGB texels, decoded
    // by the texture unit, where the renderer samples its own linear 16-bit float copy. On
    // llvmpipe that moves a pixel by at most 2 steps (mean 0.16); the bound leaves a GPU's sRGB
    // decoding room, and every departure from the README below misses it by far.
    const test::ImageDifference d = test::compareImages(drawn, *reference, 3);
    qInfo("README-only draw vs render: mean %.3f, max %d steps, %d pixels over 3", d.meanAbs,
          d.maxAbs, d.pixelsOver);
    QVERIFY(d.sameSize);
    const bool matches = d.pixelsOver <= kSize.x * kSize.y / 200 && d.meanAbs < 0.5;
    if (change.isEmpty())
        QVERIFY2(matches,
                 qPrintable(
                     QString("mean %1 steps, %2 pixels over 3").arg(d.meanAbs).arg(d.pixelsOver)));
    else
        QVERIFY2(!matches, qPrintable("drawn as render draws it although " + change));
}

QTEST_APPLESS_MAIN(PackageReadmeTest)
#include "PackageReadmeTest.moc"
