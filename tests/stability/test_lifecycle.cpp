// Case 12 (docs/stability.md): lifetime. pf_destroy after 1000-2000 steps with the context
// current; two simulations stepping alternately in one context, each matching a lone run; and
// create / step / destroy 1000 times without host memory growing (the GL objects of such a loop
// are counted name by name in GlState.CreateDestroyLoopLeaksNoGlObjects).
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "stability/stability.h"

namespace pf::test {
namespace {

// Resident set size of this process in KiB (/proc/self/statm, Linux).
long resident_kib() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return -1;
    long pages = 0, resident = 0;
    const int read = std::fscanf(f, "%ld %ld", &pages, &resident);
    std::fclose(f);
    return read == 2 ? resident * 4 : -1;
}

class Lifecycle : public Stability {};

TEST_P(Lifecycle, DestroyAfterThousandsOfSteps) {
    const pf_sim_desc d = desc(4, 4, 4, 0.1f);
    pf_sim* sim = nullptr;
    ASSERT_EQ(pf_create(&d, &sim), PF_OK);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.2f, 0.3f, 0.2f};
    ASSERT_EQ(pf_fill_box(sim, lo, hi, nullptr), PF_OK);
    // 2000 steps with the default (balanced) preset, 1000 with the others (CI's fast mode).
    const int steps = GetParam() == PF_QUALITY_BALANCED || long_mode() ? 2000 : 1000;
    for (int s = 0; s < steps; ++s) ASSERT_EQ(pf_step(sim, 1.0f / 60.0f), PF_OK) << "step " << s;
    check(sim, d, 2 * 3 * 2 * 8, "after the long run");
    pf_destroy(sim);
    // The context is intact: a new simulation works in it.
    SimPtr again = create(d);
    ASSERT_TRUE(again);
    expect_usable(again.get(), d, "a new simulation after the long one");
}

// Two simulations, stepped alternately, each end bit-identical to the same scene run alone:
// nothing of one leaks into the other through GL state or shared objects.
TEST_P(Lifecycle, TwoSimulationsSteppingAlternately) {
    const pf_sim_desc d = desc(8, 8, 8, 0.1f);
    const float lo_a[3] = {0, 0, 0}, hi_a[3] = {0.4f, 0.5f, 0.4f};
    const float lo_b[3] = {0.3f, 0, 0.3f}, hi_b[3] = {0.8f, 0.3f, 0.8f};
    auto make = [&](const float* lo, const float* hi) {
        SimPtr s = create(d);
        EXPECT_EQ(pf_fill_box(s.get(), lo, hi, nullptr), PF_OK);
        return s;
    };
    SimPtr a = make(lo_a, hi_a), b = make(lo_b, hi_b);
    for (int f = 0; f < 60; ++f) {
        ASSERT_EQ(pf_step(a.get(), 1.0f / 60.0f), PF_OK);
        ASSERT_EQ(pf_step(b.get(), 1.0f / 60.0f), PF_OK);
    }
    SimPtr lone_a = make(lo_a, hi_a);
    for (int f = 0; f < 60; ++f) ASSERT_EQ(pf_step(lone_a.get(), 1.0f / 60.0f), PF_OK);
    SimPtr lone_b = make(lo_b, hi_b);
    for (int f = 0; f < 60; ++f) ASSERT_EQ(pf_step(lone_b.get(), 1.0f / 60.0f), PF_OK);
    const ParticleState pa = read_all(a.get()), pla = read_all(lone_a.get());
    const ParticleState pb = read_all(b.get()), plb = read_all(lone_b.get());
    ASSERT_EQ(pa.pos.size(), pla.pos.size());
    ASSERT_EQ(pb.pos.size(), plb.pos.size());
    EXPECT_EQ(std::memcmp(pa.pos.data(), pla.pos.data(), pa.pos.size() * 4), 0) << "a differs from its lone run";
    EXPECT_EQ(std::memcmp(pb.pos.data(), plb.pos.data(), pb.pos.size() * 4), 0) << "b differs from its lone run";
}

// 1000 rounds with the default (balanced) preset; in CI's fast mode 200 with the other presets (their
// extra programs compile in every round), PF_STABILITY_LONG: 10,000 with every preset.
TEST_P(Lifecycle, CreateStepDestroyAThousandTimes) {
    const int rounds = long_mode() ? 10000 : (GetParam() == PF_QUALITY_BALANCED ? 1000 : 200);
    const pf_sim_desc d = desc(4, 4, 4, 0.1f);
    long after_warmup = 0;
    for (int round = 0; round < rounds; ++round) {
        pf_sim* sim = nullptr;
        ASSERT_EQ(pf_create(&d, &sim), PF_OK) << "round " << round << ": " << last_log();
        const float lo[3] = {0, 0, 0}, hi[3] = {0.2f, 0.2f, 0.2f};
        ASSERT_EQ(pf_fill_box(sim, lo, hi, nullptr), PF_OK);
        ASSERT_EQ(pf_step(sim, 1.0f / 60.0f), PF_OK);
        pf_destroy(sim);
        if (round == rounds / 10) after_warmup = resident_kib();
    }
    const long end = resident_kib();
    ASSERT_GT(after_warmup, 0);
    record("resident_growth_kib", double(end - after_warmup));
    record("rounds", rounds);
    // The driver's caches settle in the first rounds; after them, a leak of even one small
    // allocation per round (1 KiB x 900) would show. Bound: 2 MiB.
    EXPECT_LT(end - after_warmup, 2048) << "host memory grew over " << rounds << " create/destroy rounds";
}

PF_STABILITY_PRESETS(Lifecycle);

}  // namespace
}  // namespace pf::test
