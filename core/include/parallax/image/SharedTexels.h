#pragma once
// The texels of a map, shared between copies until one of them writes (copy on write). A document
// state, its undo history, a background bake and the renderer all hold the same 8192² map this
// way: copying a HeightField or a MaterialAssets costs a pointer, not 256 MB. Qt's containers
// share so; the core is Qt-free, and the standard library has no such container.
//
// Rules as for Qt's implicit sharing: copies may go to other threads; one object is not written
// from two threads at once, nor copied while it is written; a pointer or reference got from a
// non-const accessor is invalidated by copying the object (write through it after a copy and both
// copies change).

#include <atomic>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
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

    // A copy shares the texels: neither side may write in place any more until it detaches.
    SharedTexels(const SharedTexels& other) : m_data(other.m_data) { other.forget(); }
    SharedTexels& operator=(const SharedTexels& other) {
        if (this != &other) {
            m_data = other.m_data;
            other.forget();
            m_own = nullptr;
        }
        return *this;
    }
    SharedTexels(SharedTexels&& other) noexcept
        : m_data(std::move(other.m_data)), m_own(std::exchange(other.m_own, nullptr)) {}
    SharedTexels& operator=(SharedTexels&& other) noexcept {
        if (this != &other) {
            m_data = std::move(other.m_data);
            m_own = std::exchange(other.m_own, nullptr);
        }
        return *this;
    }
    ~SharedTexels() = default;

    std::size_t size() const { return m_data ? m_data->size() : 0; }
    bool empty() const { return size() == 0; }

    const T* data() const { return m_data ? m_data->data() : nullptr; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size(); }
    const T& operator[](std::size_t i) const { return (*m_data)[i]; }

    // Writing: first make the texels this object's own. Once they are, a write costs one test
    // (no reference count is read) until the object is copied.
    T* data() { return writable(); }
    T* begin() { return writable(); }
    T* end() { return writable() + size(); }
    T& operator[](std::size_t i) { return writable()[i]; }

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
    T* writable() { return m_own ? m_own : detach(); }
    T* detach() {
        if (!m_data)
            return nullptr;
        if (m_data.use_count() > 1) {
            m_data = std::make_shared<std::vector<T>>(*m_data);
        } else {
            // The count was read relaxed: the acquire makes the other owners' reads, released
            // when they let go (their decrement), happen before the writes that follow.
            std::atomic_thread_fence(std::memory_order_acquire);
        }
        m_own = m_data->data();
        return m_own;
    }
    // A copy forgets the source's ownership. Several threads may copy one object at once, so
    // copies write it atomically; the owner's own reads and writes are plain (its loops keep the
    // pointer in a register): the rules above keep them apart from any copy.
    void forget() const { std::atomic_ref<T*>(m_own).store(nullptr, std::memory_order_relaxed); }
    static const std::vector<T>& emptyVector() {
        static const std::vector<T> none;
        return none;
    }

    std::shared_ptr<std::vector<T>> m_data;
    // The texels while this object is known to be their only owner (it detached, and has not been
    // copied since); null otherwise.
    alignas(std::atomic_ref<T*>::required_alignment) mutable T* m_own = nullptr;
};

} // namespace px
