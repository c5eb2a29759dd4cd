// Byte streams of snapshots (pf_save_snapshot / pf_restore_snapshot): plain values appended in
// host byte order, read back with bounds checks. A snapshot is for the same build on the same
// machine (docs/integration.md §2): no endianness or layout conversion.
#pragma once
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace pf {

class ByteWriter {
public:
    explicit ByteWriter(std::vector<uint8_t>& out) : out_(out) {}
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>, "plain values only");
        put_bytes(&value, sizeof value);
    }
    void put_bytes(const void* data, size_t bytes) {
        const auto* p = static_cast<const uint8_t*>(data);
        out_.insert(out_.end(), p, p + bytes);
    }

private:
    std::vector<uint8_t>& out_;
};

class ByteReader {
public:
    ByteReader(const uint8_t* data, size_t bytes) : p_(data), end_(data + bytes) {}
    // False (and nothing read) when fewer than sizeof(T) bytes are left.
    template <typename T>
    bool get(T& value) {
        static_assert(std::is_trivially_copyable_v<T>, "plain values only");
        return get_bytes(&value, sizeof value);
    }
    bool get_bytes(void* data, size_t bytes) {
        if (size_t(end_ - p_) < bytes) return false;
        std::memcpy(data, p_, bytes);
        p_ += bytes;
        return true;
    }
    // The next `bytes` bytes without copying them (nullptr if short).
    const uint8_t* take(size_t bytes) {
        if (size_t(end_ - p_) < bytes) return nullptr;
        const uint8_t* at = p_;
        p_ += bytes;
        return at;
    }
    size_t left() const { return size_t(end_ - p_); }

private:
    const uint8_t* p_;
    const uint8_t* end_;
};

}  // namespace pf
