// The substep as a table of stages (Box2D v3's solver stages are the model): the core passes,
// the pressure solver and the effects that are on each register entries, in order, and a
// substep runs the table from top to bottom. The simulation rebuilds it whenever what decides
// its entries changes (parameters, features, a snapshot); a fused pass replaces the entries it
// fuses instead of lines in a function. docs/design.md §4 lists the entries.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace pf {

// What one substep's entries may ask that the table's shape does not say.
struct SubstepContext {
    bool correct_volume = false;  // the volume correction runs in this substep
    bool half_move = false;       // the particles move half the substep (the leapfrog's last move of a step)
};

class SubstepTable {
public:
    using Run = std::function<void(const SubstepContext&)>;

    void clear() { entries_.clear(); }
    // Appends an entry; it anchors the entries inserted after it.
    void add(std::string name, Run run);
    // Inserts an entry after the entry named `anchor` and after every entry inserted there
    // before it (they run in insertion order). False (and nothing added) without such an anchor.
    bool insert_after(const std::string& anchor, std::string name, Run run);
    // Replaces the work of the entry named `name`. False when there is none.
    bool replace(const std::string& name, Run run);
    // Runs every entry, from the one named `first` on (from the top when empty); nothing when
    // there is no entry of that name.
    void run(const SubstepContext& context, const std::string& first = {}) const;
    // The entries' names, in order.
    std::vector<std::string> names() const;

private:
    struct Entry {
        std::string name;
        std::string anchor;  // the entry it was inserted after (its own name for added ones)
        Run run;
    };
    std::vector<Entry> entries_;
};

}  // namespace pf
