#include "widgets/Hints.h"

#include <QObject>

namespace px::studio::hints {

QString heightScale() {
    return QObject::tr("height_scale: how deep the lowest point (height 0, black) lies below the "
                       "polygon, in uv units (fractions of a tile). 0 turns parallax off.");
}
QString depthMap() {
    return QObject::tr("The map is a depth map (white = deep, like LearnOpenGL's depthMap and "
                       "many _disp files): it is read inverted, as 1 - value.");
}
QString heightChannel() {
    return QObject::tr("Which channel of the height file holds the height.");
}
QString tiling() {
    return QObject::tr("How many times the tile repeats across the mesh in u and v.");
}
QString wrap() {
    return QObject::tr("Repeat: the surface continues across tile edges. Clamp: rays that leave "
                       "the tile are discarded, so the edges show their real relief.");
}
QString minLayers() {
    return QObject::tr(
        "minLayers: march layers looking straight down. Parallax occlusion mapping "
        "(Tatarchuk 2006) picks numLayers = mix(maxLayers, minLayers, |dot(N, V)|); too few shows "
        "stair steps.");
}
QString maxLayers() {
    return QObject::tr("maxLayers: march layers at grazing angles, where a ray crosses the most "
                       "texels. Raise it if slanted views show slices.");
}
QString qualityRange() {
    return QObject::tr("u_parallax_quality (x, y): the quality looking straight down and at "
                       "grazing angles; layers = quality x 50. The same setting as min/max "
                       "layers, in the two-value form of common POM shaders.");
}
QString binarySteps() {
    return QObject::tr("numBinarySteps: halvings of the last layer after the march (relief "
                       "mapping). Each halves the remaining error.");
}
QString secantSteps() {
    return QObject::tr("Secant (regula falsi) steps after the march: each interpolates where the "
                       "ray crosses the surface between the last two samples.");
}
QString stepCap(Technique technique) {
    switch (technique) {
    case Technique::Cone:
    case Technique::RelaxedCone:
        return QObject::tr("Cone step cap: the most cone steps a ray takes. A ray that runs out "
                           "stops short of the surface (undershoots): raise it for grazing "
                           "views.");
    case Technique::Pyramid:
        return QObject::tr("The most max-mip nodes a ray visits before it gives up.");
    default:
        return QObject::tr("The most cells the exact reference walks before it gives up.");
    }
}
QString selfShadow() {
    return QObject::tr("Soft self-shadowing: a second march from the hit towards the light "
                       "(Tatarchuk 2006's soft shadows, the ParallaxSoftShadowMultiplier of common "
                       "shaders), so bumps cast shadows.");
}
QString shadowSoftness() {
    return QObject::tr("0: hard shadows, any occluder blocks the light. 1: soft, the penumbra "
                       "grows with how far below the occluding surface the light ray passes.");
}
QString normalSource() {
    return QObject::tr("Shading normals: from the normal map, or computed from the height map "
                       "in the shader (4-tap central differences or a 3x3 Sobel filter).");
}
QString normalGreen() {
    return QObject::tr("Green channel of the normal map: OpenGL (Y+: glTF, Godot, Unity, "
                       "Blender) or DirectX (Y-: Unreal).");
}
QString lighting() {
    return QObject::tr(
        "Blinn-Phong as in the classic parallax demos, or metallic-roughness for materials headed "
        "to engines.");
}
QString lightAzimuth() {
    return QObject::tr("Where the light comes from, around the vertical axis: 0 from the front "
                       "(+z, down the image on the plane), 90 from the right (+x, along u). "
                       "Ctrl+drag in a view to move the light.");
}
QString lightElevation() {
    return QObject::tr("Height of the light above the ground plane: 90 is straight above, low "
                       "values make long shadows. Ctrl+drag in a view.");
}
QString mesh() {
    return QObject::tr("The shape the material is shown on: a built-in one or a recent mesh file.");
}
QString environment() {
    return QObject::tr("Light from a whole sky: the built-in one (its sun where the light is when "
                       "chosen) or an equirectangular HDR/EXR. The light stays as the sun and "
                       "casts the relief's shadows.");
}
QString loadMesh() {
    return QObject::tr("Show the material on your own mesh: OBJ or glTF (.obj, .gltf, .glb), also "
                       "by dropping the file on the window. Remembered for this material.");
}
QString linkViews() {
    return QObject::tr("Linked: every viewport shares the camera and the light, so techniques "
                       "compare on the same view. Unlink to move one view alone.");
}
QString heatMap() {
    return QObject::tr("Show each pixel's error in texels (blue 0, green 0.5, yellow 1, red 2 or "
                       "more): the technique's own (its hit against the exact hit on the mip "
                       "level it reads), or, from the arrow, the filtering's (that level's exact "
                       "hit against level 0's).");
}
QString wipe() {
    return QObject::tr("A/B wipe: the left of this view shows its technique, the right another "
                       "one; drag the divider.");
}
QString technique(Technique t) {
    switch (t) {
    case Technique::None:
        return QObject::tr("Plain texturing: no normal mapping, no parallax.");
    case Technique::Normal:
        return QObject::tr("Normal mapping only: lighting, no parallax.");
    case Technique::Offset:
        return QObject::tr("Parallax with offset limiting: one height fetch, uv shifted by "
                           "h * height_scale. Cheap, swims at grazing angles.");
    case Technique::Steep:
        return QObject::tr("Steep parallax: march the layers until the ray is below the "
                           "surface.");
    case Technique::Pom:
        return QObject::tr("Parallax occlusion mapping: march, then interpolate between the last "
                           "two layers.");
    case Technique::Relief:
        return QObject::tr("Relief mapping: march, then binary search in the last layer.");
    case Technique::Secant:
        return QObject::tr("March, then secant steps towards the crossing.");
    case Technique::Cone:
        return QObject::tr("Cone step mapping: safe steps as large as the cone map allows. Needs "
                           "a cone map (Maps > Bake cone).");
    case Technique::RelaxedCone:
        return QObject::tr("Relaxed cone stepping, then the cells of the last step solved exactly. "
                           "Needs a relaxed cone map (Maps > Bake relaxed cone).");
    case Technique::Pyramid:
        return QObject::tr("Maximum-mipmap traversal: skips empty space level by level, exact "
                           "cell solve at the end.");
    case Technique::Exact:
        return QObject::tr("The exact intersection: every crossed cell solved exactly. The "
                           "reference every error is measured against; slow.");
    }
    return {};
}
QString viewportHelp() {
    return QObject::tr("Drag or arrows: orbit. Wheel or +/-: zoom. Ctrl+drag or Ctrl+arrows: move "
                       "the light. Double-click: reset the camera. Click: make this the active "
                       "viewport.");
}

} // namespace px::studio::hints
