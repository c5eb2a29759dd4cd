// The one place that maps pf_p2g values to particle-to-grid schemes.
#include "sim/transfer/atomic/atomic_p2g.h"
#include "sim/transfer/p2g_scheme.h"
#include "sim/transfer/sorted_gather/sorted_gather_p2g.h"
#include "sim/transfer/tiled/tiled_p2g.h"

namespace pf {

std::unique_ptr<P2gScheme> make_p2g_scheme(pf_p2g kind) {
    switch (kind) {
        case PF_P2G_FIXED_POINT: return std::make_unique<AtomicP2g>(AtomicP2g::Sums::fixed_point);
        case PF_P2G_FLOAT_ATOMIC: return std::make_unique<AtomicP2g>(AtomicP2g::Sums::floats);
        case PF_P2G_SORTED_GATHER: return std::make_unique<SortedGatherP2g>();
        case PF_P2G_TILED: return std::make_unique<TiledP2g>();
        default: return nullptr;
    }
}

}  // namespace pf
