#pragma once
// The texels of a map, shared between copies until one of them writes (copy on write). A document
// state, its undo history, a background bake and the renderer all hold the same 8192² map this
// way: copying a HeightField or a MaterialAssets costs a pointer, not 256 MB. Qt's containers
// share so; the core is Qt-free, and the standard library has no such container.
//
// Rules as for Qt's implicit sharing: copies may go to other threads; one object is not written
// from two threads at once; a pointer or reference got from a non-const accessor is invalidated
// by copying the object (write through it after a copy and both copies change).

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

namespace px {

template <class T> class SharedTexels {
public:
    using value_type = T;
    using size_type = std::size_t;
    using iterator = T*;
    using const_iterator = const T*;

    SharedTexels() = default;
    SharedTexels(std::size_t count, const T& value)
        : m_data(std::make_shared<std::vector<T>>(count, value)) {}
    SharedTexels(std::vector<T> values) // NOLINT(google-explicit-constructor): a vector is texels
        : m_data(std::make_shared<std::vector<T>>(std::move(values))) {}
    SharedTexels(std::initializer_list<T> values)
        : m_data(std::make_shared<std::vector<T>>(values)) {}

    std::size_t size() const { return m_data ? m_data->size() : 0; }
    bool empty() const { return size() == 0; }

    const T* data() const { return m_data ? m_data->data() : nullptr; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size(); }
    const T& operator[](std::size_t i) const { return (*m_data)[i]; }

    // Writing: first make the texels this object's own.
    T* data() {
        detach();
        return m_data ? m_data->data() : nullptr;
    }
    T* begin() { return data(); }
    T* end() { return data() + size(); }
    T& operator[](std::size_t i) {
        detach();
        return (*m_data)[i];
    }

    // For interfaces that take a vector (read only).
    const std::vector<T>& vector() const { return m_data ? *m_data : emptyVector(); }

    // Which texels these are, as a weak handle (it keeps nothing alive): the same for copies,
    // another once a write detaches. Compare with std::owner_less.
    std::weak_ptr<const void> identity() const { return m_data; }
    // Whether the two hold the same texels in memory (not a copy of them).
    bool sharesWith(const SharedTexels& other) const { return m_data && m_data == other.m_data; }

    friend bool operator==(const SharedTexels& a, const SharedTexels& b) {
        return a.sharesWith(b) || a.vector() == b.vector();
    }

private:
    void detach() {
        if (m_data && m_data.use_count() > 1)
            m_data = std::make_shared<std::vector<T>>(*m_data);
    }
    static const std::vector<T>& emptyVector() {
        static const std::vector<T> none;
        return none;
    }

    std::shared_ptr<std::vector<T>> m_data;
};

} // namespace px
