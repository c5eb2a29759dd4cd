// A fixed-capacity list of an effect's objects (force fields, obstacles) named by ids that stay
// valid until the object is removed. Ids count up from 1 and are never reused, so a stale id is
// refused rather than editing another object. The live objects are kept contiguous, in the
// order they were added (the order the GPU records are uploaded in).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "api/log.h"
#include "pf/pf.h"
#include "sim/snapshot_io.h"

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
    T* find(uint32_t id) { return const_cast<T*>(std::as_const(*this).find(id)); }
    const T* find(uint32_t id) const {
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
    // Snapshots: item size, count, next id, then each id and item.
    void save(ByteWriter& out) const {
        out.put(uint32_t(sizeof(T)));
        out.put(uint32_t(items_.size()));
        out.put(next_id_);
        for (size_t i = 0; i < items_.size(); ++i) {
            out.put(ids_[i]);
            out.put(items_[i]);
        }
    }
    // Reads what save() wrote into `out` (a fresh list); `valid(item)` checks each object. Empty
    // string on success, else what is wrong.
    template <typename Valid>
    static std::string load(ByteReader& in, ObjectList& out, Valid&& valid) {
        uint32_t item_bytes = 0, count = 0;
        if (!in.get(item_bytes) || !in.get(count) || !in.get(out.next_id_)) return "truncated object list";
        if (item_bytes != sizeof(T)) return "object size " + std::to_string(item_bytes) + ", this build's is " + std::to_string(sizeof(T));
        if (count > Capacity) return std::to_string(count) + " objects, more than the capacity " + std::to_string(Capacity);
        for (uint32_t i = 0; i < count; ++i) {
            uint32_t id = 0;
            T item{};
            if (!in.get(id) || !in.get(item)) return "truncated object list";
            if (id == 0 || id >= out.next_id_ || (!out.ids_.empty() && id <= out.ids_.back()))
                return "object ids out of order or beyond the next id";
            if (!valid(item)) return "an invalid object";
            out.ids_.push_back(id);
            out.items_.push_back(item);
        }
        return {};
    }
    uint32_t size() const { return uint32_t(items_.size()); }

    // The object API's three edits (pf_add_obstacle, pf_set_sink, ...): refused with a logged
    // message (`fn` first) when the list is full (PF_ERROR_CAPACITY; `what` names the objects)
    // or the id names no object (PF_ERROR_INVALID_ARGUMENT), changing nothing then.
    pf_result add_checked(const T& item, uint32_t* out_id, const Log& log, const char* fn, const char* what) {
        if (full()) {
            return log.error(PF_ERROR_CAPACITY, std::string(fn) + ": already " + std::to_string(Capacity) + " " + what +
                                                    " (the most a simulation holds); remove one first");
        }
        const uint32_t id = add(item);
        if (out_id) *out_id = id;
        return PF_OK;
    }
    pf_result set_checked(uint32_t id, const T& item, const Log& log, const char* fn) {
        T* slot = find(id);
        if (!slot) return unknown_id(id, log, fn);
        *slot = item;
        return PF_OK;
    }
    pf_result remove_checked(uint32_t id, const Log& log, const char* fn) {
        return remove(id) ? PF_OK : unknown_id(id, log, fn);
    }
    // PF_ERROR_INVALID_ARGUMENT for an id that names no object.
    static pf_result unknown_id(uint32_t id, const Log& log, const char* fn) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": no object has id " + std::to_string(id));
    }

private:
    std::vector<T> items_;
    std::vector<uint32_t> ids_;
    uint32_t next_id_ = 1;
};

// What an effect that uploads its object list inherits: the host list, read with list() and
// changed through edit(), which marks the GPU copy stale (dirty_) for the next step's upload.
template <typename T, uint32_t Capacity>
class UploadedObjects {
public:
    using List = ObjectList<T, Capacity>;
    const List& list() const { return list_; }
    List& edit() {
        dirty_ = true;
        return list_;
    }

protected:
    List list_;
    bool dirty_ = true;  // the GPU copy differs from list_
};

}  // namespace pf
