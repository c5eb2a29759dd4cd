#!/usr/bin/env python3
"""Does a poured viscous rope coil? (docs/effects.md, "Coiling"; the runs: docs/notes/2026-11-28-rope-coiling.md). A disc emitter pours a
rope of radius a0 at speed U0 from height H onto the floor of a square tank; every sample the
rope's centre is found just above the heap it lays (the lowest 1-cell layers that hold no more
than a few rope cross-sections) and in fixed layers, and its direction from the nozzle's axis is
unwrapped over time. Steady coiling turns that direction the same way turn after turn; folding
swings it back and forth. Prints one line a sample and a summary; --out saves the series (npz).

usage: PFLIP_LIBRARY=build/libpflip.so PYTHONPATH=python scripts/rope_coiling.py
           [--cells 64 128 64] [--dx 0.001] [--radius 0.002] [--height 0.1] [--speed 0.2]
           [--viscosity 100] [--seconds 4] [--sample-dt 0.0083333] [--out rope.npz]
"""
import argparse
import pathlib

import numpy as np

try:
    import pflip  # not needed to analyse exported frames (--ply)
except ImportError:
    pflip = None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cells", type=int, nargs=3, default=(64, 128, 64), help="grid x y z (y up)")
    ap.add_argument("--dx", type=float, default=0.001, help="cell size, m")
    ap.add_argument("--radius", type=float, default=0.002, help="nozzle radius a0, m")
    ap.add_argument("--height", type=float, default=0.1, help="nozzle height H above the floor, m")
    ap.add_argument("--speed", type=float, default=0.2, help="pouring speed U0, m/s")
    ap.add_argument("--viscosity", type=float, default=100.0, help="dynamic viscosity, Pa s (density 1000)")
    ap.add_argument("--iterations", type=int, default=200, help="viscosity CG iterations a substep at most")
    ap.add_argument("--tolerance", type=float, default=1e-3, help="viscosity CG relative residual")
    ap.add_argument("--rounds", type=int, default=1, help="pf_viscosity.coupling_rounds")
    ap.add_argument("--quality", default="balanced", help="fast, balanced or accurate")
    ap.add_argument("--transfer", choices=("preset", "pic_flip", "apic"), default="preset",
                    help="grid-particle transfer over the preset's")
    ap.add_argument("--flip-ratio", type=float, help="FLIP share of PIC/FLIP over the preset's (0 = PIC)")
    ap.add_argument("--max-substeps", type=int, default=16)
    ap.add_argument("--seconds", type=float, default=4.0)
    ap.add_argument("--sample-dt", type=float, default=1.0 / 120.0, help="frame step between samples, s")
    ap.add_argument("--layers", type=float, nargs="*", default=(0.1, 0.2, 0.3),
                    help="fixed layers to follow, as fractions of H above the floor")
    ap.add_argument("--out", help="save the series here (npz)")
    ap.add_argument("--ply", help="analyse pf_headless --export-ply frames in this folder instead of running "
                                  "(--sample-dt is then the scene's frame_dt; the geometry options must match)")
    args = ap.parse_args()

    dx, grid = args.dx, np.array(args.cells)
    axis = np.array([grid[0] * dx / 2, grid[2] * dx / 2])
    a0, U0, H = args.radius, args.speed, args.height
    nu = args.viscosity / 1000.0
    print(f"rope a0 {a0 * 1e3:.2f} mm ({a0 / dx:.1f} cells) U0 {U0} m/s from H {H * 1e3:.0f} mm "
          f"(H/d {H / (2 * a0):.1f}); nu {nu:g} m2/s, {args.rounds} coupling rounds, {args.quality} preset, transfer "
          f"{args.transfer}, flip ratio {'preset' if args.flip_ratio is None else args.flip_ratio}, Re {U0 * 2 * a0 / nu:.3g}, "
          f"H (g/nu^2)^(1/3) {H * (9.81 / nu ** 2) ** (1 / 3):.3g}, grid {grid.tolist()} of {dx * 1e3:g} mm", flush=True)

    ppc = 8.0  # particles a cell a full cell holds (the emitter's spacing)
    rope_layer = ppc * np.pi * (a0 / dx) ** 2  # particles in one cell-thick layer of the nozzle's rope
    series = {k: [] for k in ("t", "heap", "off_x", "off_z", "speed", "n", "substeps", "flags", "visc_it", "max_speed")}
    fixed = [[] for _ in args.layers]
    source = ply_frames(args.ply, args.sample_dt) if args.ply else simulated_frames(args, axis)
    for k, (t, pos, vel, st) in enumerate(source):
        rel = pos[:, [0, 2]] - axis
        layer = np.floor(pos[:, 1] / dx).astype(np.int64)
        counts = np.bincount(layer.clip(0), minlength=int(grid[1]))
        # The heap: the highest layer below the nozzle holding more than three rope cross-sections.
        top = int(H / dx)
        crowded = np.nonzero(counts[:top] > 3.0 * rope_layer)[0]
        heap = int(crowded.max()) + 1 if crowded.size else 0
        band = (layer >= heap + 1) & (layer < heap + 3)
        off = rel[band].mean(0) if band.any() else np.array([np.nan, np.nan])
        speed = float(np.linalg.norm(vel[band].mean(0))) if band.any() else np.nan
        figures = (st.substeps, st.flags, st.viscosity_iterations, st.max_speed) if st else (0, 0, 0, 0.0)
        for name, v in zip(series, (t, heap * dx, off[0], off[1], speed, len(pos)) + figures):
            series[name].append(v)
        for i, f in enumerate(args.layers):
            sel = layer == int(f * H / dx)
            fixed[i].append(rel[sel].mean(0) if sel.any() else np.array([np.nan, np.nan]))
        if k % max(1, int(round(0.1 / args.sample_dt))) == 0:
            print(f"t {t:.3f} n {len(pos)} substeps {figures[0]} flags {figures[1]:#x} visc_it {figures[2]} "
                  f"max_speed {figures[3]:.3f} heap {heap * dx * 1e3:.1f} mm offset {np.hypot(*off) * 1e3:.2f} mm "
                  f"at {np.degrees(np.arctan2(off[1], off[0])):.0f} deg", flush=True)

    s = {k: np.array(v) for k, v in series.items()}
    for label, offs in [("above the heap", np.stack([s["off_x"], s["off_z"]], 1))] + \
            [(f"layer {f:g} H", np.array(v)) for f, v in zip(args.layers, fixed)]:
        summarise(label, s["t"], offs, dx, s["speed"])
    if args.out:
        np.savez(args.out, **s, fixed=np.array(fixed), layers=np.array(args.layers), args=str(vars(args)))


def simulated_frames(args, axis):
    """(t, positions, velocities, stats) after each step of the pour, run here."""
    pflip.frame.create_context()
    grid = tuple(int(g) for g in args.cells)
    poured = 8.0 * np.pi * args.radius ** 2 * args.speed * args.seconds / args.dx ** 3  # 8 particles a cell
    sim = pflip.Simulation(grid_size=grid, cell_size=args.dx, max_particles=int(1.25 * poured) + 4096,
                           features=int(pflip.Feature.EMITTERS | pflip.Feature.VISCOSITY))
    sim.set_quality(pflip.Quality[args.quality.upper()])
    params = sim.params
    params.max_substeps = args.max_substeps
    if args.transfer != "preset":
        params.transfer = pflip.Transfer[args.transfer.upper()]
    if args.flip_ratio is not None:
        params.flip_ratio = args.flip_ratio
    sim.params = params
    sim.set_viscosity(viscosity=args.viscosity, iterations=args.iterations, tolerance=args.tolerance,
                      coupling_rounds=args.rounds)
    a0, U0 = args.radius, args.speed
    sim.add_emitter(shape="disc", position=(axis[0], args.height, axis[1]), rotation=(1, 0, 0, 0), radius=a0,
                    velocity=(0, -U0, 0), rate=np.pi * a0 * a0 * U0, rate_unit="volume_per_second")
    for k in range(int(round(args.seconds / args.sample_dt))):
        sim.step(args.sample_dt)
        pos, vel = sim.read_particles()
        yield (k + 1) * args.sample_dt, pos, vel, sim.stats()


def ply_frames(folder, frame_dt):
    """(t, positions, velocities, None) of pf_headless --export-ply's frame_NNNN.ply (binary; frame
    0, the initial fill, skipped), frame_dt apart."""
    for path in sorted(pathlib.Path(folder).glob("frame_*.ply")):
        number = int(path.stem.split("_")[1])
        if number == 0:
            continue
        data = path.read_bytes()
        end = data.index(b"end_header\n") + len(b"end_header\n")
        if b"binary_little_endian" not in data[:end]:
            raise SystemExit(f"{path}: not a binary PLY (pf_headless --ply-format binary)")
        xyz_v = np.frombuffer(data, dtype="<f4", offset=end).reshape(-1, 6)
        yield number * frame_dt, xyz_v[:, :3], xyz_v[:, 3:], None


def summarise(label, t, offs, dx, speed, window=0.25):
    """Turns of the offset's direction, counted where the rope is off the axis by more than half a
    cell; the share of samples turning the net way; the offset's median. Then the longest coil:
    consecutive windows of `window` seconds that each turn at least a quarter turn the same way,
    with its rate, radius and the rope's speed there (steady coiling lays the rope at its own
    speed: 2 pi f R = U)."""
    r = np.hypot(offs[:, 0], offs[:, 1])
    ok = np.isfinite(r) & (r > 0.5 * dx)
    if ok.sum() < 3:
        print(f"{label}: on the axis (offset above half a cell in {int(ok.sum())} samples)")
        return
    phi = np.unwrap(np.arctan2(offs[ok, 1], offs[ok, 0]))
    d = np.diff(phi)
    net = (phi[-1] - phi[0]) / (2 * np.pi)
    same = float(np.mean(np.sign(d) == np.sign(net))) if d.size else 0.0
    span = (phi.max() - phi.min()) / (2 * np.pi)
    print(f"{label}: {int(ok.sum())} samples off the axis from t {t[ok][0]:.2f} s, offset median "
          f"{np.median(r[ok]) * 1e3:.2f} mm (max {r[ok].max() * 1e3:.2f}), net turns {net:+.2f}, "
          f"span {span:.2f} turns, {same * 100:.0f}% of steps turn the net way")
    tt, rr, uu = t[ok], r[ok], speed[ok]
    edges = np.arange(tt[0], tt[-1], window)
    turns = [phi[(tt >= a) & (tt < a + window)] for a in edges]
    turns = np.array([w[-1] - w[0] if w.size > 1 else 0.0 for w in turns]) / (2 * np.pi)
    best, start, run = (0, 0), 0, 0
    for i, w in enumerate(turns):
        same_way = run and np.sign(w) == np.sign(turns[i - 1])
        run = run + 1 if abs(w) >= 0.25 and (same_way or run == 0) else (1 if abs(w) >= 0.25 else 0)
        if run and run > best[0]:
            best = (run, i - run + 1)
    if best[0] < 2:
        print(f"  no coil: no two {window} s windows in a row turn a quarter turn the same way")
        return
    a, b = edges[best[1]], edges[best[1]] + best[0] * window
    m = (tt >= a) & (tt < b)
    n_turns = float(turns[best[1]:best[1] + best[0]].sum())
    f, radius, u = abs(n_turns) / (b - a), float(np.median(rr[m])), float(np.nanmedian(uu[m]))
    print(f"  longest coil {a:.2f}-{b:.2f} s: {n_turns:+.2f} turns, {f:.2f} Hz, radius {radius * 1e3:.2f} mm, rope "
          f"speed {u:.3f} m/s, 2 pi f R / U {2 * np.pi * f * radius / u:.2f}")


if __name__ == "__main__":
    main()
