#include "standing_wave.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace pfs {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

double StandingWave::wavenumber() const { return kPi / length; }

double StandingWave::omega() const {
    const double k = wavenumber();
    return std::sqrt((gravity * k + tension * k * k * k / density) * std::tanh(k * depth));
}

double StandingWave::period() const { return 2.0 * kPi / omega(); }

std::vector<float> StandingWave::lattice(uint32_t seed, double jitter, double amplitude_override) const {
    const double a = amplitude_override >= 0.0 ? amplitude_override : amplitude, k = wavenumber(), s = dx / 2;
    const int nx = int(std::lround(length / s)), ny = int(std::ceil((depth + a) / s)),
              nz = std::max(1, int(std::lround(thickness / s)));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter, jitter);
    std::vector<float> pos;
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                const double px = (x + 0.5 + u(rng)) * s, py = (y + 0.5 + u(rng)) * s, pz = (z + 0.5 + u(rng)) * s;
                // The lattice site decides (not the jittered point), so every column holds whole sites.
                if ((y + 0.5) * s >= depth + a * std::cos(k * (x + 0.5) * s)) continue;
                pos.insert(pos.end(), {float(px), float(py), float(pz)});
            }
    return pos;
}

double StandingWave::wave_energy_per_mass() const {
    const double k = wavenumber();
    return (gravity + tension * k * k / density) * amplitude * amplitude / (4.0 * depth);
}

double StandingWave::surface_energy_per_mass(double a) const {
    const double k = wavenumber();
    return tension * k * k * a * a / (4.0 * density * depth);
}

double mode_amplitude(const StandingWave& wave, const float* pos, size_t count) {
    const int nx = std::max(1, int(std::lround(wave.length / wave.dx)));
    std::vector<double> column(size_t(nx), 0.0);
    for (size_t i = 0; i < count; ++i) {
        const int c = std::clamp(int(std::floor(pos[i * 3] / wave.dx)), 0, nx - 1);
        column[size_t(c)] += 1.0;
    }
    // A particle is dx^3 / 8 of liquid at rest; a column's cross-section is dx * thickness.
    const double height_per_particle = wave.dx * wave.dx / (8.0 * wave.thickness), k = wave.wavenumber();
    double a = 0;
    for (int c = 0; c < nx; ++c) a += column[size_t(c)] * height_per_particle * std::cos(k * (c + 0.5) * wave.dx);
    return 2.0 * a / nx;
}

double mechanical_energy_per_mass(const StandingWave& wave, const float* pos, const float* vel, size_t count) {
    double e = 0;
    for (size_t i = 0; i < count; ++i) {
        const double vx = vel[i * 3], vy = vel[i * 3 + 1], vz = vel[i * 3 + 2];
        e += 0.5 * (vx * vx + vy * vy + vz * vz) + wave.gravity * pos[i * 3 + 1];
    }
    return count ? e / double(count) : 0.0;
}

WaveFit fit_wave(const std::vector<double>& t, const std::vector<double>& a) {
    WaveFit fit;
    if (t.size() != a.size() || t.size() < 3) return fit;
    double peak = 0;
    for (double v : a) peak = std::max(peak, std::abs(v));
    // A crossing counts once the signal has been beyond +-band on the other side since the
    // previous one, so noise near zero cannot add crossings.
    const double band = 0.05 * peak;
    std::vector<double> crossings;
    std::vector<std::pair<double, double>> extrema;  // (time, |a|) of each half cycle's largest |a|
    int side = a[0] > band ? 1 : (a[0] < -band ? -1 : 0);
    std::pair<double, double> best{t[0], std::abs(a[0])};
    for (size_t i = 1; i < a.size(); ++i) {
        if (std::abs(a[i]) > best.second) best = {t[i], std::abs(a[i])};
        const int now = a[i] > band ? 1 : (a[i] < -band ? -1 : 0);
        if (now != 0 && side != 0 && now != side) {
            // The zero crossing between the last sample on the old side and this one.
            size_t j = i;
            while (j > 1 && (a[j - 1] > 0) == (a[i] > 0)) --j;
            const double t0 = t[j - 1], t1 = t[j], a0 = a[j - 1], a1 = a[j];
            crossings.push_back(t0 + (t1 - t0) * a0 / (a0 - a1));
            extrema.push_back(best);
            best = {t[i], std::abs(a[i])};
        }
        if (now != 0) side = now;
    }
    fit.crossings = uint32_t(crossings.size());
    if (crossings.size() >= 3)
        fit.period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    fit.extrema = uint32_t(extrema.size());
    if (extrema.size() >= 2 && fit.period > 0) {
        double st = 0, sl = 0, stt = 0, stl = 0;
        const double n = double(extrema.size());
        for (const auto& [te, ae] : extrema) {
            const double l = std::log(std::max(ae, 1e-12));
            st += te, sl += l, stt += te * te, stl += te * l;
        }
        const double slope = (n * stl - st * sl) / std::max(1e-300, n * stt - st * st);
        fit.loss_per_period = 1.0 - std::exp(slope * fit.period);
    }
    return fit;
}

}  // namespace pfs
