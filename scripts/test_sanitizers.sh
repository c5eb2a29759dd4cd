#!/usr/bin/env bash
# Sanitizer stage: the library, the engine and internal GoogleTest suites and the random-API
# fuzzer built with -fsanitize=address,undefined,float-cast-overflow into build-asan/ (samples
# off: they are covered by the main tree and the libFuzzer stage), then every test of that
# tree. Any sanitizer report aborts its test. Only the GL driver's own leaks are suppressed
# (tests/sanitizers/lsan.supp says why for each line).
#   PF_FUZZ_SECONDS=600 scripts/test_sanitizers.sh -R fuzz.api    # a longer API fuzz by hand
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DPF_SANITIZE=ON -DPF_BUILD_SAMPLES=OFF \
      -DPF_FUZZ_SECONDS="${PF_FUZZ_SECONDS:-60}" -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >/dev/null
cmake --build build-asan
supp="$PWD/tests/sanitizers"
# intercept_tls_get_addr=0: GCC 12's sanitizer runtime takes a malloc'd dynamic TLS block that
# happens to start 16 bytes into a page for one with a pre-2.25 glibc header and reads garbage
# before it; LeakSanitizer's tracer then segfaults at exit ("Tracer caught signal 11") after a
# test passed (CI, 2026-11-25). Runtimes up to GCC 13 and LLVM 16 have it (Mudlet/Mudlet#9930).
export ASAN_OPTIONS="intercept_tls_get_addr=0:detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
# Not here: the Python client, the engine samples (Panda3D, through that client) and the package
# consumers load the sanitized libpflip into unsanitized programs (ASan must come first), and
# ASan's quarantine holds freed memory, so the resident-memory bound of the create/destroy loop
# measures ASan, not pflip. Nor the long physics runs, whose length adds no host code: the
# sanitizers check the library's own code, which a step runs the same way in the first second as
# in the tenth (the GL driver is not instrumented). Each runs in the main stage, and shorter tests
# here run the same passes, presets and entry points:
# - the standing waves (Waves.*, 8 minutes of physics in the main stage) and the dam breaks of
#   Volume.* (the short dam breaks of P2gSchemes.* and VorticityConfinement.* remain);
# - the stability suite's physics cases (Presets/*: each creates, fills and steps through the
#   same entry points as the engine suite's tests); its Lifecycle (create, step and destroy under
#   every preset, thousands of steps), Degenerate (degenerate grids and inputs) and Packed cases
#   remain;
# - the spun tank (DomainMotion: the turned and accelerated tanks remain), the emitter's volume
#   rate (Emitters: its other tests remain), APIC's angular momentum (TransferAdvection: APIC
#   runs in the accurate preset's cases), the noisy tanks of the volume correction, the decaying
#   vortex (VorticityConfinement: two other tests remain), the dam break's surface roughness
#   (RenderSurface: the resting pool's tests remain) and the floating box (ObstacleArguments: the
#   other obstacle tests remain);
# - the viscosity's physics runs (Viscosity.*: its reports, reruns, snapshot and bad-input tests
#   and the reference comparison of its solve remain), and the surface tension's (SurfaceTension.*:
#   its reruns, snapshot and bad-input tests remain; the smallest-grid drop and the Laplace
#   pressure run the same passes longer);
# - of the solver ladder (Every/Ladder.*, each solver x transfer x integrator), the mirrored
#   corners (the same host calls as its dam break, which remains with the closed box and the
#   shaft), and the thousands of steps before a destroy under the fast and accurate presets
#   (Lifecycle: the balanced one remains; the steps' host code is the same under each).
# Measured on CI's 2 cores (2026-11-26): 600 s of the stage's 1,170 s of tests; the ladder's
# corners and the two lifecycles 31 s more (2026-12-05).
ctest --output-on-failure -j"$(nproc)" \
      -E "^(python|package|engines)\.|CreateStepDestroyAThousandTimes|^Waves\.|^Volume\.(Issue)?DamBreak|^Presets/(Column|Corners|LongRun|Obstacles|SourceStability|LargeSteps|Jet|ClosedBox|ObstacleStability|Walls)\.|SpunTank|VolumeRateFills|ApicKeepsAngularMomentum|KeepsA(Small)?NoisyTank|KeepsADecayingVortex|DamBreakRoughness|FloatingBoxOfHalfDensity|^Viscosity\.(ShearVortex|NoSlipWalls|ShallowCavity|OnlyRemovesEnergy|VeryViscousBlob|LiquidAtRest)|^SurfaceTension\.(CubeRelaxes|SmallDropStays|CapillaryWave|SubstepsFollow)|^SurfaceTensionPressure\.|^Every/Ladder\.TwoMirroredCornersAgree/|^Presets/Lifecycle\.DestroyAfterThousandsOfSteps/(fast|accurate)" "$@"
