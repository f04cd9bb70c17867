#pragma once
// Owning handles for GL object names, deleted on destruction (on the context current then: a
// handle must die while its context, or one sharing with it, is current). Move-only.

#include <utility>

namespace px::gl {

enum class ObjectKind {
    Texture,
    Buffer,
    VertexArray,
    Framebuffer,
    Renderbuffer,
    Program,
    Shader,
    Query
};

class Object {
public:
    Object() = default;
    // Creates a new name (shaders: see createShader).
    explicit Object(ObjectKind kind);
    // Takes ownership of an existing name.
    Object(ObjectKind kind, unsigned id) : m_kind(kind), m_id(id) {}
    ~Object() { reset(); }
    Object(Object&& o) noexcept : m_kind(o.m_kind), m_id(std::exchange(o.m_id, 0u)) {}
    Object& operator=(Object&& o) noexcept {
        if (this != &o) {
            reset();
            m_kind = o.m_kind;
            m_id = std::exchange(o.m_id, 0u);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    unsigned id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset();

private:
    ObjectKind m_kind = ObjectKind::Texture;
    unsigned m_id = 0;
};

} // namespace px::gl
