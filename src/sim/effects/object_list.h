// A fixed-capacity list of an effect's objects (force fields, obstacles) named by ids that stay
// valid until the object is removed. Ids count up from 1 and are never reused, so a stale id is
// refused rather than editing another object. The live objects are kept contiguous, in the
// order they were added (the order the GPU records are uploaded in).
#pragma once
#include <cstdint>
#include <vector>

namespace pf {

template <typename T, uint32_t Capacity>
class ObjectList {
public:
    static constexpr uint32_t kCapacity = Capacity;
    bool full() const { return items_.size() >= Capacity; }
    // Adds `item` (the caller checked full()) and returns its id.
    uint32_t add(const T& item) {
        items_.push_back(item);
        ids_.push_back(next_id_);
        return next_id_++;
    }
    // The object named `id`, or nullptr.
    T* find(uint32_t id) {
        for (size_t i = 0; i < ids_.size(); ++i)
            if (ids_[i] == id) return &items_[i];
        return nullptr;
    }
    bool remove(uint32_t id) {
        for (size_t i = 0; i < ids_.size(); ++i) {
            if (ids_[i] != id) continue;
            items_.erase(items_.begin() + long(i));
            ids_.erase(ids_.begin() + long(i));
            return true;
        }
        return false;
    }
    const std::vector<T>& items() const { return items_; }
    // The objects for in-place updates of state the host keeps with them (ids unchanged).
    std::vector<T>& items_mutable() { return items_; }
    // The ids of items(), in the same order.
    const std::vector<uint32_t>& ids() const { return ids_; }
    uint32_t size() const { return uint32_t(items_.size()); }

private:
    std::vector<T> items_;
    std::vector<uint32_t> ids_;
    uint32_t next_id_ = 1;
};

}  // namespace pf
