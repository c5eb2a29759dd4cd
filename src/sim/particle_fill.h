// pf_fill_box's particle placement: a regular sub-lattice of m^3 samples per cell
// (m^3 = fill_particles_per_cell), each jittered by a hash of (seed, call, sample), kept when
// inside the box clipped to the domain. Deterministic and independent of the GPU.
#pragma once
#include <cstdint>
#include <vector>

#include "pf/pf.h"

namespace pf {

class FillLattice {
public:
    FillLattice(const pf_sim_desc& desc, const float lo[3], const float hi[3]);
    // Number of particles generate() will produce.
    uint64_t count() const;
    // Appends 3 floats per particle to xyz.
    void generate(uint32_t seed, uint32_t call, std::vector<float>& xyz) const;

private:
    const pf_sim_desc& desc_;
    double lo_[3], hi_[3];
    int64_t first_[3] = {}, last_[3] = {};  // sample index range per axis (inclusive, exclusive)
    int m_ = 1;
    bool empty_ = true;
};

}  // namespace pf
