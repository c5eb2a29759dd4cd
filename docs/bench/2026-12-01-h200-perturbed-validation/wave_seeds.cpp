// The thin tank's standing wave (tests/engine/test_waves.cpp's, 1 cell thick, 3 periods) from
// another lattice seed: loss a period, period error and largest energy gain, as the test
// measures them. Arguments: advection (0 Euler, 3 leapfrog), lattice seed, cfl, quality, cells
// thick. Built against a build tree (a measurement, not part of the build):
//   g++ -O2 -std=c++17 wave_seeds.cpp -Iinclude -Ibuild/include -Isamples/common -Lbuild \
//       -Wl,-rpath,$PWD/build -lpflip build/samples/libpf_egl_context.a \
//       build/samples/libpf_standing_wave.a -lEGL -o wave_seeds
//   for s in 17 1 2 3 4 5 6 7; do ./wave_seeds 0 $s; ./wave_seeds 3 $s; done
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <vector>
#include <pf/pf.h>
#include "egl_context.h"
#include "standing_wave.h"
int main(int argc, char** argv) {
    int adv = atoi(argv[1]); int seed = atoi(argv[2]); float cfl = argc > 3 ? atof(argv[3]) : 1.0f;
    int quality = argc > 4 ? atoi(argv[4]) : PF_QUALITY_BALANCED;
    uint32_t thick = argc > 5 ? atoi(argv[5]) : 1;
    pfs::EglContext ctx;
    pfs::StandingWave wave; wave.thickness = thick * wave.dx;
    pf_sim_desc d = pf_default_sim_desc();
    d.grid_size[0] = 64; d.grid_size[1] = 48; d.grid_size[2] = thick; d.cell_size = float(wave.dx);
    d.max_particles = 64 * 48 * thick * 8; d.gl_get_proc_address = pfs::get_proc;
    pf_quality_params(pf_quality(quality), &d.params);
    d.params.advection = pf_advection(adv); d.params.cfl = cfl;
    pf_sim* sim; if (pf_create(&d, &sim) != PF_OK) return 1;
    std::vector<float> pos = wave.lattice(seed);
    std::vector<float> vel(pos.size(), 0.f);
    pf_add_particles(sim, pos.data(), vel.data(), uint32_t(pos.size() / 3));
    double e_wave = wave.wave_energy_per_mass();
    double e0 = pfs::mechanical_energy_per_mass(wave, pos.data(), vel.data(), pos.size() / 3);
    std::vector<double> t{0.0}, a{pfs::mode_amplitude(wave, pos.data(), pos.size() / 3)};
    int frames = int(std::ceil(3.0 * wave.period() * 60.0));
    double gain = 0; uint32_t n = 0;
    for (int f = 1; f <= frames; ++f) {
        pf_step(sim, 1.0f / 60.0f);
        if (f % 2 != 0 && f != frames) continue;
        pf_get_particle_count(sim, &n);
        pos.resize(n * 3); vel.resize(n * 3);
        pf_read_particles(sim, 0, n, pos.data(), vel.data());
        double e = pfs::mechanical_energy_per_mass(wave, pos.data(), vel.data(), n);
        t.push_back(f / 60.0); a.push_back(pfs::mode_amplitude(wave, pos.data(), n));
        gain = std::max(gain, (e - e0) / e_wave);
    }
    pfs::WaveFit fit = pfs::fit_wave(t, a);
    pf_stats st{}; st.struct_size = sizeof st; pf_get_stats(sim, &st);
    printf("adv %d seed %d cfl %.1f q %d: loss %.2f%% period %+.2f%% gain %.3f substeps %u\n", adv, seed, cfl, quality,
           100 * fit.loss_per_period, 100 * (fit.period / wave.period() - 1), gain, st.substeps);
    pf_destroy(sim);
}
