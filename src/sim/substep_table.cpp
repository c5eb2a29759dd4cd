#include "sim/substep_table.h"

#include <utility>

namespace pf {

void SubstepTable::add(std::string name, Run run) {
    std::string anchor = name;
    entries_.push_back(Entry{std::move(name), std::move(anchor), std::move(run)});
}

bool SubstepTable::insert_after(const std::string& anchor, std::string name, Run run) {
    size_t at = entries_.size();
    for (size_t i = 0; i < entries_.size(); ++i) {
        if (entries_[i].name == anchor || (at != entries_.size() && entries_[i].anchor == anchor)) at = i;
    }
    if (at == entries_.size()) return false;
    entries_.insert(entries_.begin() + std::ptrdiff_t(at + 1), Entry{std::move(name), anchor, std::move(run)});
    return true;
}

bool SubstepTable::replace(const std::string& name, Run run) {
    for (Entry& e : entries_) {
        if (e.name == name) {
            e.run = std::move(run);
            return true;
        }
    }
    return false;
}

void SubstepTable::run(const SubstepContext& context, const std::string& first) const {
    bool on = first.empty();
    for (const Entry& e : entries_) {
        on = on || e.name == first;
        if (on) e.run(context);
    }
}

std::vector<std::string> SubstepTable::names() const {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
}

}  // namespace pf
