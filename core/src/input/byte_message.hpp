#pragma once
// Plain bytes between a reading child process and its caller (load_model, load_animation): the
// child writes values in order, the caller reads them back in the same order.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace popup {

struct ByteWriter {
    std::string bytes;
    template <class T> void put(const T& value)
    {
        bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    template <class T> void put_all(const std::vector<T>& values)
    {
        put(std::uint64_t(values.size()));
        bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void put_text(const std::string& text)
    {
        put(std::uint64_t(text.size()));
        bytes.append(text);
    }
};

/// Reads what a ByteWriter wrote; `fine` turns false (and stays) when the bytes run out.
struct ByteReader {
    const std::string& bytes;
    size_t at = 0;
    bool fine = true;
    template <class T> T get()
    {
        T value{};
        if (at + sizeof(T) > bytes.size()) {
            fine = false;
            return value;
        }
        std::memcpy(static_cast<void*>(&value), bytes.data() + at, sizeof(T));
        at += sizeof(T);
        return value;
    }
    template <class T> void get_all(std::vector<T>& values)
    {
        const auto n = get<std::uint64_t>();
        if (!fine || n > (bytes.size() - at) / sizeof(T)) {
            fine = false;
            return;
        }
        values.resize(n);
        std::memcpy(static_cast<void*>(values.data()), bytes.data() + at, n * sizeof(T));
        at += n * sizeof(T);
    }
    std::string get_text()
    {
        const auto n = get<std::uint64_t>();
        if (!fine || n > bytes.size() - at) {
            fine = false;
            return {};
        }
        at += n;
        return bytes.substr(at - n, n);
    }
    /// True when every byte was read and none was missing.
    bool whole() const { return fine && at == bytes.size(); }
};

} // namespace popup
