#pragma once
// The green channel convention of a tangent-space normal map (docs/conventions.md §3). Here, below
// the material, because the normal baker writes either and the material names which one it reads.

namespace px {

enum class NormalGreen {
    OpenGL,  // Y+ (glTF, Godot, Unity, Blender)
    DirectX, // Y- (Unreal)
};

} // namespace px
