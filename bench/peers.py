"""Our solver beside the peers a user could pick instead, on the same mechanism in the same
run: pylinkage (its Python stepper, its fast stepper and its kinematics) and the PyPI
package ``mechanism`` (a vector-loop solver on scipy's fsolve). Ratios, not absolute times.

    .venv/bin/python bench/peers.py           # print the table (makes .venv-peers once)
    .venv/bin/python bench/peers.py --write   # and regenerate its part of docs/performance.md

The peers are installed only for this benchmark, into their own environment
(``.venv-peers``: the app's pinned requirements plus the two peers, pinned too).
"""

import math
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PEERS = ROOT / ".venv-peers"
# numba: pylinkage's fast steppers are compiled with it when it is there, and pure Python
# (60× slower at 3600) when not; a user who picks pylinkage for speed has it.
PINS = ["pylinkage==1.3.0", "mechanism==1.1.10", "numba==0.68.1"]
RESOLUTIONS = (360, 3600)  # positions per cycle: a page's default (1°) and the finest it offers


def ensure_environment() -> None:
    """Re-run this script inside .venv-peers (made on first use)."""
    python, pinned = PEERS / "bin" / "python", PEERS / "pins.txt"
    if Path(sys.prefix).resolve() == PEERS.resolve():  # (both pythons link to one binary)
        return
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(PEERS)], check=True)
    if not pinned.exists() or pinned.read_text() != "\n".join(PINS):  # new, or the pins changed
        subprocess.run([str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
                        "-r", str(ROOT / "requirements.txt"), *PINS], check=True)
        pinned.write_text("\n".join(PINS))
    os.execv(python, [str(python), __file__, *sys.argv[1:]])


def timed(run, repeat: int) -> tuple[float, object]:
    """Median time (ms) of ``repeat`` runs, and the last result."""
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times), result


def paired(ours, peer, rounds: int) -> tuple[float, float, object]:
    """Median times (ms) of ``ours`` and ``peer`` run in turn, ``rounds`` each, and the peer's
    last result. This shared machine's speed drifts by ±15 % within a minute; taking turns
    lets both sides meet the same drift, so their ratio holds where separate runs did not
    (pylinkage's fast stepper measured 40 to 66 µs in four runs of one afternoon)."""
    mine, theirs, result = [], [], None
    for _ in range(rounds):
        start = time.perf_counter()
        ours()
        middle = time.perf_counter()
        result = peer()
        mine.append(middle - start)
        theirs.append(time.perf_counter() - middle)
    return 1e3 * statistics.median(mine), 1e3 * statistics.median(theirs), result


def table(N: int) -> str:
    import numpy as np
    from mechanism import Joint, Mechanism, Vector
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    sys.path.insert(0, str(ROOT))
    from mechanisms import load_preset
    from solvers.kinematics import solve

    scene = load_preset("four-bar-crank-rocker")  # O, D = (0.4, 0); OA 0.1, AB 0.35, DB 0.3
    omega = scene.driver.speed
    phi = 2 * math.pi * np.arange(1, N + 1) / N  # the peers step from φ₂ = 0 onwards
    positions, everything = (lambda: solve(scene, phi, order=0)), (lambda: solve(scene, phi, order=2))
    ours_pos_ms, _ = timed(positions, 200)
    ours_ms, ours = timed(everything, 200)
    b, vb = ours.points["B"].z, ours.points["B"].v

    def four_bar() -> Linkage:
        origin, pivot = Ground(0.0, 0.0, name="O"), Ground(0.4, 0.0, name="D")
        crank = Crank(anchor=origin, radius=0.1, angular_velocity=2 * math.pi / N, name="A")
        rocker = RRRDyad(anchor1=crank.output, anchor2=pivot, distance1=0.35, distance2=0.3, name="B")
        linkage = Linkage([origin, pivot, crank, rocker], name="four-bar")
        linkage.set_input_velocity(crank, omega, 0.0)
        return linkage

    def error_mm(points) -> float:
        return 1e3 * float(np.max(np.abs(points - b)))

    # like for like: the linkage is built once and stepped again, as our solve reuses the
    # plan it keeps per scene (each call steps a whole turn, so it ends where it started)
    built = four_bar()
    rows = []
    mine, step_ms, steps = paired(positions, lambda: list(built.step(iterations=N)), 50)
    rows.append(("pylinkage 1.3.0, `Linkage.step` (positions)", step_ms, mine,
                 error_mm(np.array([complex(*s[3]) for s in steps])), "—"))
    mine, fast_ms, fast = paired(positions, lambda: built.step_fast(iterations=N), 400)
    rows.append(("pylinkage 1.3.0, `step_fast` (positions)", fast_ms, mine,
                 error_mm(fast[:, 3, 0] + 1j * fast[:, 3, 1]), "—"))
    mine, kin_ms, (p, v, a) = paired(everything, lambda: built.step_fast_with_kinematics(iterations=N), 400)
    # its accelerations come out per its own step convention; velocities compared here
    rate = float(np.max(np.abs(v[:, 3, 0] + 1j * v[:, 3, 1] - vb)) / np.max(np.abs(vb)))
    rows.append(("pylinkage 1.3.0, `step_fast_with_kinematics` (pos + vel + acc)", kin_ms, mine,
                 error_mm(p[:, 3, 0] + 1j * p[:, 3, 1]), f"{rate:.1e}"))

    def loop_solver():
        o, a_, b_, d = Joint("O"), Joint("A"), Joint("B"), Joint("D")
        va, vb_, vc = Vector((o, a_), r=0.1), Vector((a_, b_), r=0.35), Vector((d, b_), r=0.3)
        vd = Vector((o, d), r=0.4, theta=0, style="ground")
        mech = Mechanism(vectors=(va, vb_, vc, vd), origin=o,
                         loops=lambda x, i: va(i) + vb_(x[0]) - vc(x[1]) - vd(),
                         pos=phi, vel=np.full(N, omega), acc=np.zeros(N),
                         guess=(np.array([0.8, 1.6]), np.ones(2), np.ones(2)))
        mech.iterate()
        return b_

    loop_ms, joint = timed(loop_solver, 1)
    vel = np.array(joint.x_velocities) + 1j * np.array(joint.y_velocities)
    rows.append(("mechanism 1.1.10, `Mechanism.iterate` (pos + vel + acc)", loop_ms, ours_ms,
                 error_mm(np.array(joint.x_positions) + 1j * np.array(joint.y_positions)),
                 f"{float(np.max(np.abs(vel - vb)) / np.max(np.abs(vb))):.1e}"))
    out = [f"Four-bar crank-rocker (`four-bar-crank-rocker`), {N} positions per cycle, ω₂ = "
           f"{omega:g} s⁻¹; Mehanizmi: positions {ours_pos_ms:.3f} ms, positions + velocities + "
           f"accelerations {ours_ms:.3f} ms (median of 200). Errors against Mehanizmi's exact "
           f"solution (its loop closes to 1e-16 m).", "",
           "| peer, call | peer, ms | Mehanizmi, same work, ms | peer ÷ Mehanizmi "
           "| max position error of B, mm | max velocity error of B (rel.) |",
           "|---|---:|---:|---:|---:|---:|"]
    for name, ms, ours_same, err, rate_err in rows:
        ratio = ms / ours_same  # below 1: the peer is faster
        shown = f"{ratio:.2f}×" if ratio < 10 else f"{ratio:.0f}×"
        out.append(f"| {name} | {ms:.3g} | {ours_same:.3g} | {shown} | {err:.1e} | {rate_err} |")
    return "\n".join(out)


if __name__ == "__main__":
    ensure_environment()
    sys.path.insert(0, str(ROOT))
    from bench.publish import publish

    publish("\n\n".join(table(n) for n in RESOLUTIONS), "<!-- peers table -->", 5)
