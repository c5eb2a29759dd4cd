#include "api/handle.h"

#include <mutex>
#include <vector>

namespace pf {
namespace {

// Handle value = (generation << kIndexBits) | (slot + 1): never 0, and the generation of a slot
// grows each time the slot is freed, so an old handle to it never matches again (until its
// generation counter wraps: 2^32 reuses of one slot on 64-bit hosts, 2^16 on 32-bit ones).
constexpr unsigned kIndexBits = 16;
constexpr uintptr_t kIndexMask = (uintptr_t(1) << kIndexBits) - 1;
constexpr unsigned kGenerationBits = sizeof(uintptr_t) * 8 - kIndexBits > 32 ? 32 : sizeof(uintptr_t) * 8 - kIndexBits;
constexpr uint64_t kGenerationMask = (uint64_t(1) << kGenerationBits) - 1;

struct Slot {
    uint32_t generation = 1;  // never 0
    std::unique_ptr<SimEntry> entry;
};

struct Registry {
    std::mutex mutex;
    std::vector<Slot> slots;
    std::vector<uint32_t> free;
    uint32_t live = 0;
    pf_logger logger{};
};

Registry& registry() {
    static Registry* r = new Registry;  // never destroyed: handles may be checked during exit
    return *r;
}

pf_sim* encode(uint32_t index, uint32_t generation) {
    return reinterpret_cast<pf_sim*>((uintptr_t(generation) << kIndexBits) | uintptr_t(index + 1));
}

// The slot a handle names if its generation matches (lock held), else nullptr.
Slot* find(Registry& r, const pf_sim* handle) {
    const uintptr_t v = reinterpret_cast<uintptr_t>(handle);
    const uintptr_t index1 = v & kIndexMask;
    if (index1 == 0 || index1 > r.slots.size()) return nullptr;
    Slot& s = r.slots[index1 - 1];
    if (!s.entry || (v >> kIndexBits) != s.generation) return nullptr;
    return &s;
}

}  // namespace

pf_sim* register_sim(std::unique_ptr<SimEntry> entry) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    uint32_t index = 0;
    if (!r.free.empty()) {
        index = r.free.back();
        r.free.pop_back();
    } else {
        if (r.slots.size() >= kIndexMask) throw std::bad_alloc();  // 65535 live simulations
        r.slots.emplace_back();
        index = uint32_t(r.slots.size() - 1);
    }
    r.slots[index].entry = std::move(entry);
    ++r.live;
    return encode(index, r.slots[index].generation);
}

SimEntry* entry(const pf_sim* handle) {
    if (!handle) return nullptr;
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    Slot* s = find(r, handle);
    return s ? s->entry.get() : nullptr;
}

std::unique_ptr<SimEntry> unregister_sim(const pf_sim* handle) {
    if (!handle) return nullptr;
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    Slot* s = find(r, handle);
    if (!s) return nullptr;
    std::unique_ptr<SimEntry> out = std::move(s->entry);
    s->generation = uint32_t((uint64_t(s->generation) % kGenerationMask) + 1);  // 1..mask, never 0
    r.free.push_back(uint32_t(s - r.slots.data()));
    --r.live;
    return out;
}

uint32_t live_sim_count() {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return r.live;
}

pf_logger global_logger() {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return r.logger;
}

void set_global_logger(const pf_logger* logger) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.logger = logger ? *logger : pf_logger{};
}

pf_result global_error(pf_result code, const std::string& message) {
    return Log(global_logger()).error(code, message);  // called outside the lock
}

}  // namespace pf
